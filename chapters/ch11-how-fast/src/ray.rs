//! Step 2's ray: everything a walk needs from the ray alone, computed
//! once per ray — the box test's origin, reciprocal direction and which
//! planes it enters through, and the watertight test's shear.
use ch08::{PreparedRay, Ray32, Shear, outward};
use raystep_core::{DVec3, Interval};

/// γ₃ for `f32`: a slab's exit widened by 1 + 2γ₃ never loses a box the
/// ray touches (Ize, JCGT 2013; chapter 8, part 1).
const GAMMA3: f32 = 3.0 * (f32::EPSILON / 2.0) / (1.0 - 1.5 * f32::EPSILON);

/// The factor every exit `t` of a box test is multiplied by.
pub const WIDEN: f32 = 1.0 + 2.0 * GAMMA3;

/// A ray ready for the fast walks.
pub struct FastRay {
    /// The origin in `f32`.
    pub origin: [f32; 3],
    /// 1/d per axis (±∞ for a zero component).
    pub inverse: [f32; 3],
    /// Per axis, 1 if the ray goes toward −axis: then it enters a box
    /// through the box's max plane.
    pub negative: [usize; 3],
    /// The watertight test's origin, axes and shear, in `f64`, computed
    /// as chapter 8's [`PreparedRay`](ch08::PreparedRay) computes them.
    pub origin64: DVec3,
    /// kx, ky, kz: kz the axis the ray goes along most.
    pub axes: [usize; 3],
    /// The shear that takes the direction to (0, 0, 1).
    pub shear: DVec3,
    /// The ray itself (for the rare triangle the fast test hands to
    /// chapter 8's).
    pub ray: Ray32,
    /// Chapter 8's test, prepared, for step 2 (which keeps it).
    pub exact: Option<PreparedRay>,
}

impl FastRay {
    /// `None` for a ray with a NaN, an infinity or a zero direction: it
    /// is answered "no hit" without being traced, as chapter 8 does.
    /// With chapter 8's test prepared too if `lecture`.
    #[inline(always)]
    pub fn new(ray: &Ray32, lecture: bool) -> Option<FastRay> {
        if !ray.is_valid() {
            return None;
        }
        let inverse = ray.direction.to_array().map(|x| 1.0 / x);
        // The watertight test's steps 1 and 2: chapter 8's own.
        let shear = Shear::of(ray.direction.as_dvec3());
        Some(FastRay {
            origin: ray.origin.to_array(),
            inverse,
            negative: inverse.map(|x| usize::from(x.is_sign_negative())),
            origin64: ray.origin.as_dvec3(),
            axes: shear.axes,
            shear: shear.shear,
            ray: *ray,
            exact: lecture.then(|| PreparedRay::new(ray)),
        })
    }
}

impl FastRay {
    /// A slab's two planes along `axis`, `lo` and `hi`, in the order the
    /// ray meets them: (entry, exit). A ray toward −axis enters through
    /// the max plane.
    #[inline(always)]
    pub fn entry_exit<T>(&self, axis: usize, lo: T, hi: T) -> (T, T) {
        if self.negative[axis] == 1 {
            (hi, lo)
        } else {
            (lo, hi)
        }
    }

    /// Chapter 8's slab test along `axis` for the slab `lo ≤ x ≤ hi`:
    /// where the ray enters it, and where it leaves it, widened. The
    /// scalar kernels' step for one box on one axis.
    #[inline(always)]
    pub fn slab(&self, axis: usize, lo: f32, hi: f32) -> (f32, f32) {
        let (enter, exit) = self.entry_exit(axis, lo, hi);
        let o = self.origin[axis];
        let t0 = (enter - o) * self.inverse[axis];
        let t1 = (exit - o) * self.inverse[axis] * WIDEN;
        (t0, t1)
    }
}

/// The interval as the box tests take it: its ends in `f32` rounded
/// outward, the end widened as every exit is.
#[inline]
pub fn span(interval: Interval) -> (f32, f32) {
    (
        outward(interval.min, false),
        outward(interval.max, true) * WIDEN,
    )
}
