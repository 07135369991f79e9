//! Intel Embree 3 as a peer: its own hierarchy, its own traversal and,
//! unlike the other peers, its own triangle test (in `f32`), so its `t`
//! may differ from ours in the last bits ([`Method::own_triangle_test`]).
//!
//! The library is loaded when the bench runs, not linked: a raystep built
//! with the `embree` feature still runs where it is missing, and reports
//! Embree skipped. The few calls needed are declared here by hand; the
//! values and layouts are those of Embree 3.13's headers
//! (`embree3/rtcore_*.h`), as Debian and Intel build it.
//!
//! [`Method::own_triangle_test`]: crate::Method::own_triangle_test
use std::collections::HashMap;
use std::error::Error as _;
use std::ffi::{CStr, c_char, c_void};
use std::sync::OnceLock;
use std::time::Instant;

use libloading::Library;
use raystep_core::glam::Vec3;
use raystep_core::{DVec3, Interval, Ray32};
use raystep_world::{MeshAccelerator, MeshHit, TraceCounts};

use crate::built::Built;
use crate::embree_isa::EmbreeIsa;

/// The names the library is looked for by: the runtime package's first
/// (the unversioned link comes only with the development package).
pub const LIBRARY_NAMES: [&str; 2] = ["libembree3.so.3", "libembree3.so"];

/// What to install where it is missing.
const INSTALL: &str = "Debian: apt-get install libembree3-3";

// Opaque handles.
type RawDevice = *mut c_void;
type RawScene = *mut c_void;
type RawGeometry = *mut c_void;

// The enumerations' values (C enums, 32 bits).
const RTC_ERROR_NONE: u32 = 0;
const RTC_DEVICE_PROPERTY_VERSION: u32 = 0;
const RTC_GEOMETRY_TYPE_TRIANGLE: u32 = 0;
const RTC_BUFFER_TYPE_INDEX: u32 = 0;
const RTC_BUFFER_TYPE_VERTEX: u32 = 1;
const RTC_FORMAT_UINT3: u32 = 0x5003;
const RTC_FORMAT_FLOAT3: u32 = 0x9003;
const RTC_BUILD_QUALITY_MEDIUM: u32 = 1;
/// `RTC_SCENE_FLAG_ROBUST` (rtcore_scene.h): traversal and triangle tests
/// that avoid optimisations which may let a ray through a crack.
const RTC_SCENE_FLAG_ROBUST: u32 = 1 << 2;
const RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT: u32 = 0;
const RTC_INVALID_GEOMETRY_ID: u32 = u32::MAX;

/// `RTCIntersectContext`, as built with `RTC_MAX_INSTANCE_LEVEL_COUNT` 1
/// and `RTC_MIN_WIDTH` 0 (the release's defaults, and Debian's).
#[repr(C)]
struct IntersectContext {
    flags: u32,
    /// A filter function (none).
    filter: *const c_void,
    /// The instance stack (empty).
    inst_id: [u32; 1],
}

impl IntersectContext {
    /// What the header's inline `rtcInitIntersectContext` sets. The flag
    /// says "incoherent" for every set, primary rays too: Embree's manual
    /// ties the coherent one's gain to its ray-stream calls, and we trace
    /// one ray at a time, as for the other methods.
    fn new() -> IntersectContext {
        IntersectContext {
            flags: RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT,
            filter: std::ptr::null(),
            inst_id: [RTC_INVALID_GEOMETRY_ID],
        }
    }
}

/// `RTCRay`: origin, `tnear`, direction, time, `tfar`, mask, ID, flags.
#[repr(C, align(16))]
struct Ray {
    org: [f32; 3],
    tnear: f32,
    dir: [f32; 3],
    time: f32,
    tfar: f32,
    mask: u32,
    id: u32,
    flags: u32,
}

/// `RTCHit`: the geometric normal, barycentrics, the triangle, the
/// geometry and the instance stack.
#[repr(C, align(16))]
struct Hit {
    ng: [f32; 3],
    u: f32,
    v: f32,
    prim_id: u32,
    geom_id: u32,
    inst_id: [u32; 1],
}

/// `RTCRayHit`.
#[repr(C)]
struct RayHit {
    ray: Ray,
    hit: Hit,
}

// The headers' sizes: a mistake here would let Embree write past a ray.
const _: () = assert!(
    size_of::<Ray>() == 48
        && size_of::<Hit>() == 32
        && size_of::<RayHit>() == 80
        && size_of::<IntersectContext>() == 24
);

/// The library and the functions we call, resolved once.
struct Api {
    new_device: unsafe extern "C" fn(*const c_char) -> RawDevice,
    get_device_error: unsafe extern "C" fn(RawDevice) -> u32,
    get_device_property: unsafe extern "C" fn(RawDevice, u32) -> isize,
    release_device: unsafe extern "C" fn(RawDevice),
    new_scene: unsafe extern "C" fn(RawDevice) -> RawScene,
    set_scene_build_quality: unsafe extern "C" fn(RawScene, u32),
    set_scene_flags: unsafe extern "C" fn(RawScene, u32),
    new_geometry: unsafe extern "C" fn(RawDevice, u32) -> RawGeometry,
    set_new_geometry_buffer: unsafe extern "C" fn(
        RawGeometry,
        u32,
        u32,
        u32,
        usize,
        usize,
    ) -> *mut c_void,
    commit_geometry: unsafe extern "C" fn(RawGeometry),
    attach_geometry: unsafe extern "C" fn(RawScene, RawGeometry) -> u32,
    release_geometry: unsafe extern "C" fn(RawGeometry),
    commit_scene: unsafe extern "C" fn(RawScene),
    intersect1:
        unsafe extern "C" fn(RawScene, *mut IntersectContext, *mut RayHit),
    occluded1: unsafe extern "C" fn(RawScene, *mut IntersectContext, *mut Ray),
    release_scene: unsafe extern "C" fn(RawScene),
    /// Keeps the functions above loaded.
    _library: Library,
}

/// A loader's error with its cause (libloading's own message is only
/// "dlopen failed").
fn describe(error: &libloading::Error) -> String {
    match error.source() {
        Some(cause) => cause.to_string(),
        None => error.to_string(),
    }
}

/// The function `name` of `library`, as a `T`.
///
/// # Safety
/// `T` must be the function's type.
unsafe fn function<T: Copy>(
    library: &Library, name: &CStr,
) -> Result<T, String> {
    // SAFETY: the caller's promise.
    unsafe { library.get::<T>(name) }
        .map(|symbol| *symbol)
        .map_err(|e| describe(&e))
}

impl Api {
    /// Loads the first of `names` that is there, and its functions.
    fn load(names: &[&str]) -> Result<Api, String> {
        let mut failures = Vec::new();
        for &name in names {
            // SAFETY: loading runs the library's initialisers (Embree's
            // and TBB's), which ask nothing of their caller.
            match unsafe { Library::new(name) } {
                Ok(library) => {
                    return Api::resolve(library)
                        .map_err(|e| format!("{name}: {e}"));
                }
                Err(e) => failures.push(describe(&e)),
            }
        }
        let first = names.first().copied().unwrap_or("libembree3");
        // "not found" unless one was there but would not load
        match failures.iter().find(|f| !f.contains("No such file")) {
            None => Err(format!("{first} not found ({INSTALL})")),
            Some(failure) => Err(format!("{failure} ({INSTALL})")),
        }
    }

    fn resolve(library: Library) -> Result<Api, String> {
        // SAFETY: each type is the function's declaration in Embree 3's
        // headers (enums as u32, ssize_t as isize, size_t as usize).
        unsafe {
            Ok(Api {
                new_device: function(&library, c"rtcNewDevice")?,
                get_device_error: function(&library, c"rtcGetDeviceError")?,
                get_device_property: function(
                    &library,
                    c"rtcGetDeviceProperty",
                )?,
                release_device: function(&library, c"rtcReleaseDevice")?,
                new_scene: function(&library, c"rtcNewScene")?,
                set_scene_build_quality: function(
                    &library,
                    c"rtcSetSceneBuildQuality",
                )?,
                set_scene_flags: function(&library, c"rtcSetSceneFlags")?,
                new_geometry: function(&library, c"rtcNewGeometry")?,
                set_new_geometry_buffer: function(
                    &library,
                    c"rtcSetNewGeometryBuffer",
                )?,
                commit_geometry: function(&library, c"rtcCommitGeometry")?,
                attach_geometry: function(&library, c"rtcAttachGeometry")?,
                release_geometry: function(&library, c"rtcReleaseGeometry")?,
                commit_scene: function(&library, c"rtcCommitScene")?,
                intersect1: function(&library, c"rtcIntersect1")?,
                occluded1: function(&library, c"rtcOccluded1")?,
                release_scene: function(&library, c"rtcReleaseScene")?,
                _library: library,
            })
        }
    }
}

/// The library, loaded on first use and kept for the process's life
/// (never unloaded: TBB's threads may outlive our last call).
static API: OnceLock<Result<Api, String>> = OnceLock::new();

fn api() -> Result<&'static Api, String> {
    API.get_or_init(|| Api::load(&LIBRARY_NAMES))
        .as_ref()
        .map_err(String::clone)
}

/// An error code's name in the header.
fn error_name(code: u32) -> String {
    match code {
        1 => "RTC_ERROR_UNKNOWN".into(),
        2 => "RTC_ERROR_INVALID_ARGUMENT".into(),
        3 => "RTC_ERROR_INVALID_OPERATION".into(),
        4 => "RTC_ERROR_OUT_OF_MEMORY".into(),
        5 => "RTC_ERROR_UNSUPPORTED_CPU".into(),
        6 => "RTC_ERROR_CANCELLED".into(),
        _ => format!("error {code}"),
    }
}

/// A device, released when dropped.
struct Device {
    api: &'static Api,
    raw: RawDevice,
}

impl Device {
    fn new(
        api: &'static Api, isa: Option<EmbreeIsa>,
    ) -> Result<Device, String> {
        // "threads=N": Embree builds on as many threads as the bench's
        // pool has (`--threads`), as the appendix's parallel build does.
        // (Tracing runs on the bench's threads regardless.) "isa=…": its
        // kernels kept to that instruction set.
        let isa =
            isa.map_or(String::new(), |isa| format!(",isa={}", isa.name()));
        let threads = rayon::current_num_threads();
        let config = format!("threads={threads}{isa}\0");
        // SAFETY: a NUL-terminated string, only read during the call.
        let raw = unsafe { (api.new_device)(config.as_ptr().cast()) };
        if raw.is_null() {
            // SAFETY: a null device asks for the error of creating one.
            let code = unsafe { (api.get_device_error)(std::ptr::null_mut()) };
            return Err(format!("rtcNewDevice: {}", error_name(code)));
        }
        Ok(Device { api, raw })
    }

    /// The first error since the last call, if any, after `call`.
    fn check(&self, call: &str) -> Result<(), String> {
        // SAFETY: a live device (errors are kept per thread).
        match unsafe { (self.api.get_device_error)(self.raw) } {
            RTC_ERROR_NONE => Ok(()),
            code => Err(format!("{call}: {}", error_name(code))),
        }
    }

    /// Embree's version as MAJOR·10000 + MINOR·100 + PATCH.
    fn version(&self) -> u32 {
        // SAFETY: a live device.
        let version = unsafe {
            (self.api.get_device_property)(
                self.raw,
                RTC_DEVICE_PROPERTY_VERSION,
            )
        };
        u32::try_from(version).unwrap_or(0)
    }
}

impl Drop for Device {
    fn drop(&mut self) {
        // SAFETY: our reference, given back once; the scenes made on the
        // device hold their own.
        unsafe { (self.api.release_device)(self.raw) }
    }
}

/// Our triangles as an application would hand them over: each distinct
/// corner once, in `f32` (exact for OBJ meshes, which are read in `f32`),
/// and three indices per triangle in our order, so that Embree's
/// primitive ID is our triangle's index.
struct IndexedMesh {
    vertices: Vec<[f32; 3]>,
    indices: Vec<[u32; 3]>,
}

impl IndexedMesh {
    fn new(triangles: &[[DVec3; 3]]) -> IndexedMesh {
        let mut seen: HashMap<[u32; 3], u32> =
            HashMap::with_capacity(triangles.len());
        let mut vertices = Vec::with_capacity(triangles.len());
        let indices = triangles
            .iter()
            .map(|corners| {
                corners.map(|p| {
                    let p = p.as_vec3().to_array();
                    *seen.entry(p.map(f32::to_bits)).or_insert_with(|| {
                        vertices.push(p);
                        u32::try_from(vertices.len() - 1)
                            .expect("fewer than 2³² vertices")
                    })
                })
            })
            .collect();
        IndexedMesh { vertices, indices }
    }
}

/// A committed scene of one triangle mesh, asked one ray at a time.
/// Dropping it releases the scene, then the device.
struct Scene {
    raw: RawScene,
    device: Device,
}

// SAFETY: a committed scene is only read by rtcIntersect1 and
// rtcOccluded1, which Embree lets many threads call at once (each with its
// own ray and context, as here).
unsafe impl Sync for Scene {}

impl Scene {
    /// Builds the scene of `mesh` on `device`, committed; with Embree's
    /// robust flag if `robust`.
    fn new(
        device: Device, mesh: &IndexedMesh, robust: bool,
    ) -> Result<Scene, String> {
        let api = device.api;
        // SAFETY: a live device.
        let raw = unsafe { (api.new_scene)(device.raw) };
        if raw.is_null() {
            return Err(device
                .check("rtcNewScene")
                .err()
                .unwrap_or_else(|| "rtcNewScene: no scene".into()));
        }
        let scene = Scene { raw, device };
        // Embree's default, set to say so: a binned SAH without spatial
        // splits (HIGH adds them), as ours and the other peers build.
        // SAFETY: a live scene, not committed yet.
        unsafe {
            (api.set_scene_build_quality)(scene.raw, RTC_BUILD_QUALITY_MEDIUM)
        };
        if robust {
            // SAFETY: a live scene, not committed yet.
            unsafe { (api.set_scene_flags)(scene.raw, RTC_SCENE_FLAG_ROBUST) };
        }
        if !mesh.indices.is_empty() {
            scene.add(mesh)?;
        }
        // SAFETY: a live scene, its geometry committed.
        unsafe { (api.commit_scene)(scene.raw) };
        scene.device.check("rtcCommitScene")?;
        Ok(scene)
    }

    /// Adds `mesh` as a triangle geometry.
    fn add(&self, mesh: &IndexedMesh) -> Result<(), String> {
        let api = self.device.api;
        // SAFETY: a live device.
        let geometry = unsafe {
            (api.new_geometry)(self.device.raw, RTC_GEOMETRY_TYPE_TRIANGLE)
        };
        if geometry.is_null() {
            self.device.check("rtcNewGeometry")?;
            return Err("rtcNewGeometry: no geometry".into());
        }
        let filled = self
            .buffer(
                geometry,
                RTC_BUFFER_TYPE_INDEX,
                RTC_FORMAT_UINT3,
                &mesh.indices,
            )
            .and_then(|()| {
                self.buffer(
                    geometry,
                    RTC_BUFFER_TYPE_VERTEX,
                    RTC_FORMAT_FLOAT3,
                    &mesh.vertices,
                )
            });
        // SAFETY: a live geometry and scene; the scene keeps a reference
        // to what it holds, so ours is given back either way.
        unsafe {
            if filled.is_ok() {
                (api.commit_geometry)(geometry);
                (api.attach_geometry)(self.raw, geometry);
            }
            (api.release_geometry)(geometry);
        }
        filled?;
        self.device.check("rtcAttachGeometry")
    }

    /// Gives `geometry` a new buffer (slot 0) holding `items`.
    fn buffer<T: Copy>(
        &self, geometry: RawGeometry, kind: u32, format: u32, items: &[T],
    ) -> Result<(), String> {
        // SAFETY: a live geometry; the stride is the item's size, a
        // multiple of 4 as Embree asks.
        let data = unsafe {
            (self.device.api.set_new_geometry_buffer)(
                geometry,
                kind,
                0,
                format,
                size_of::<T>(),
                items.len(),
            )
        };
        if data.is_null() {
            self.device.check("rtcSetNewGeometryBuffer")?;
            return Err("rtcSetNewGeometryBuffer: no buffer".into());
        }
        // SAFETY: `data` is Embree's new buffer of `items.len()` items of
        // this size, 16-byte aligned, ours to fill before the commit.
        unsafe {
            std::ptr::copy_nonoverlapping(
                items.as_ptr(),
                data.cast::<T>(),
                items.len(),
            );
        }
        Ok(())
    }

    /// `ray` over `interval` (Embree's starts at 0 at the earliest; an
    /// infinite end is allowed), all geometry masked in.
    fn ray(ray: &Ray32, interval: Interval) -> Ray {
        Ray {
            org: ray.origin.to_array(),
            tnear: interval.min.max(0.0) as f32,
            dir: ray.direction.to_array(),
            time: 0.0,
            tfar: interval.max as f32,
            mask: u32::MAX,
            id: 0,
            flags: 0,
        }
    }
}

impl Drop for Scene {
    fn drop(&mut self) {
        // SAFETY: our reference, given back once, before the device's.
        unsafe { (self.device.api.release_scene)(self.raw) }
    }
}

/// Embree counts nothing: the counts are left as they are.
impl MeshAccelerator for Scene {
    fn closest_hit(
        &self, ray: &Ray32, interval: Interval, _counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        if !ray.is_valid() {
            return None;
        }
        let mut query = RayHit {
            ray: Scene::ray(ray, interval),
            hit: Hit {
                ng: [0.0; 3],
                u: 0.0,
                v: 0.0,
                prim_id: u32::MAX,
                geom_id: RTC_INVALID_GEOMETRY_ID,
                inst_id: [RTC_INVALID_GEOMETRY_ID],
            },
        };
        let mut context = IntersectContext::new();
        // SAFETY: a committed scene; the context and the ray (aligned to
        // 16 bytes, as Embree asks) live through the call.
        unsafe {
            (self.device.api.intersect1)(self.raw, &mut context, &mut query)
        };
        // a hit sets the geometry, and tfar to its t
        (query.hit.geom_id != RTC_INVALID_GEOMETRY_ID).then_some(MeshHit {
            triangle: query.hit.prim_id,
            t: f64::from(query.ray.tfar),
        })
    }

    fn any_hit(
        &self, ray: &Ray32, interval: Interval, _counts: &mut TraceCounts,
    ) -> bool {
        if !ray.is_valid() {
            return false;
        }
        let mut query = Scene::ray(ray, interval);
        let mut context = IntersectContext::new();
        // SAFETY: as in `closest`.
        unsafe {
            (self.device.api.occluded1)(self.raw, &mut context, &mut query)
        };
        // a hit sets tfar to −∞
        query.tfar == f32::NEG_INFINITY
    }
}

/// Can Embree run here? Its version (MAJOR·10000 + MINOR·100 + PATCH),
/// or why not: the library is missing, or a device or a scene cannot be
/// made, or a one-triangle scene answers four rays wrongly (structures
/// laid out otherwise than ours). Asked once, the answer kept.
pub fn probe() -> Result<u32, String> {
    static PROBE: OnceLock<Result<u32, String>> = OnceLock::new();
    PROBE.get_or_init(|| self_test(api()?)).clone()
}

fn self_test(api: &'static Api) -> Result<u32, String> {
    let device = Device::new(api, None)?;
    let version = device.version();
    let triangle = [[DVec3::ZERO, DVec3::X, DVec3::Y]];
    let scene = Scene::new(device, &IndexedMesh::new(&triangle), false)?;
    // straight down onto the triangle (t = 2) and beside it
    let down = |x: f32, y: f32| Ray32 {
        origin: Vec3::new(x, y, 2.0),
        direction: Vec3::NEG_Z,
    };
    let (onto, beside) = (down(0.25, 0.25), down(0.75, 0.75));
    let (all, short) = (Interval::FORWARD, Interval::new(0.0, 1.5));
    let counts = &mut TraceCounts::default();
    let right = matches!(
        scene.closest_hit(&onto, all, counts),
        Some(MeshHit { triangle: 0, t }) if (t - 2.0).abs() < 1e-6
    ) && scene.closest_hit(&beside, all, counts).is_none()
        && scene.any_hit(&onto, all, counts)
        && !scene.any_hit(&onto, short, counts);
    if right {
        Ok(version)
    } else {
        Err("a one-triangle scene answered wrongly".into())
    }
}

/// Builds Embree's scene over `triangles`. Only offered once [`probe`]
/// has passed, so a failure here (memory) stops the bench.
///
/// Timed from the indexed mesh to a committed scene: filling Embree's
/// buffers and its build. Finding the shared corners (our triangles come
/// apart) and the device (one per application) are not timed.
/// With `isa`, its kernels are kept to that instruction set.
pub fn build(
    triangles: &[[DVec3; 3]], robust: bool, isa: Option<EmbreeIsa>,
) -> Built {
    let api = api().unwrap_or_else(fail);
    let mesh = IndexedMesh::new(triangles);
    let device = Device::new(api, isa).unwrap_or_else(fail);
    let start = Instant::now();
    let scene = Scene::new(device, &mesh, robust).unwrap_or_else(fail);
    Built {
        build_ms: start.elapsed().as_secs_f64() * 1e3,
        tracer: Box::new(scene),
        bytes: None,
        tree: None,
    }
}

fn fail<T>(why: String) -> T {
    panic!("Embree: {why}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::run::OWN_TEST_TOLERANCE;
    use ch08::MeshBruteForce;

    #[test]
    fn a_missing_library_is_named_with_its_package() {
        let Err(why) = Api::load(&["libembree3-missing.so.3"]) else {
            panic!("a library that is not there loaded");
        };
        assert_eq!(
            why,
            "libembree3-missing.so.3 not found (Debian: apt-get install \
             libembree3-3)"
        );
    }

    #[test]
    fn shared_corners_are_stored_once() {
        let (a, b, c, d) = (DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ONE);
        let mesh = IndexedMesh::new(&[[a, b, c], [c, b, d]]);
        assert_eq!(mesh.vertices.len(), 4);
        assert_eq!(mesh.indices, [[0, 1, 2], [2, 1, 3]]);
    }

    /// Where the library is installed: Embree's answers, with its default
    /// kernels and kept to each instruction set this CPU has, are brute
    /// force's, `t` within its tolerance.
    #[test]
    fn embree_agrees_with_brute_force() {
        let Ok(api) = api() else {
            eprintln!("Embree is not installed: not tested");
            return;
        };
        self_test(api).expect("the self-test passes");
        // a bumpy sheet of 2·16² triangles, rays down onto it and aslant
        let n = 16;
        let at = |i: usize, j: usize| {
            let (x, y) = (i as f64 / n as f64, j as f64 / n as f64);
            DVec3::new(x, y, 0.1 * (7.0 * x).sin() * (5.0 * y).cos())
        };
        let mut triangles = Vec::new();
        for i in 0..n {
            for j in 0..n {
                let (p, q) = (at(i, j), at(i + 1, j));
                let (r, s) = (at(i, j + 1), at(i + 1, j + 1));
                triangles.extend([[p, q, s], [p, s, r]]);
            }
        }
        // Its default kernels, and those of every instruction set this CPU
        // has (`--embree-isa`).
        let here = [
            (EmbreeIsa::Sse2, true),
            (EmbreeIsa::Sse42, is_x86_feature_detected!("sse4.2")),
            (EmbreeIsa::Avx, is_x86_feature_detected!("avx")),
            (EmbreeIsa::Avx2, is_x86_feature_detected!("avx2")),
            (EmbreeIsa::Avx512, is_x86_feature_detected!("avx512vl")),
        ];
        let isas = here.iter().filter(|(_, has)| *has).map(|(isa, _)| *isa);
        for isa in std::iter::once(None).chain(isas.map(Some)) {
            agrees_on_a_bumpy_sheet(&triangles, isa);
        }
    }

    /// Embree robust, kept to `isa`, against brute force on 1 000 rays.
    fn agrees_on_a_bumpy_sheet(
        triangles: &[[DVec3; 3]], isa: Option<EmbreeIsa>,
    ) {
        let built = build(triangles, true, isa);
        let brute = MeshBruteForce(triangles);
        let counts = &mut TraceCounts::default();
        let mut hits = 0;
        for k in 0..1000 {
            let u = (k as f32 * 0.618_034).fract() * 1.4 - 0.2;
            let v = (k as f32 * 0.754_878).fract() * 1.4 - 0.2;
            let ray = Ray32 {
                origin: Vec3::new(u, v, 1.0),
                direction: Vec3::new(0.3 * (u - 0.5), -0.2 * v, -1.0),
            };
            for interval in [Interval::FORWARD, Interval::new(0.0, 0.9)] {
                let (ours, theirs) = (
                    brute
                        .closest_hit(&ray, interval, counts)
                        .map(|h| h.t as f32),
                    built
                        .tracer
                        .closest_hit(&ray, interval, counts)
                        .map(|h| h.t as f32),
                );
                match (ours, theirs) {
                    (None, None) => {}
                    (Some(a), Some(b)) => {
                        hits += 1;
                        let tolerance = OWN_TEST_TOLERANCE * a.max(b);
                        assert!((a - b).abs() <= tolerance, "{isa:?} ray {k}");
                    }
                    _ => panic!("{isa:?} ray {k}: {ours:?} against {theirs:?}"),
                }
                assert_eq!(
                    brute.any_hit(&ray, interval, counts),
                    built.tracer.any_hit(&ray, interval, counts),
                    "{isa:?} ray {k}"
                );
            }
        }
        assert!(hits > 300, "{isa:?}: {hits} hits");
    }
}
