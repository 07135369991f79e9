//! The box kernels against each other: SSE and the scalar test give the
//! same hits and entry `t`s on random nodes and rays (zero direction
//! components, origins on planes and empty slots included), and a
//! compressed node's boxes contain the boxes it was made from, their
//! planes exact `f32`s, at every scale from 10⁻⁶ to 10⁷ and far from
//! the origin.
use ch08::{Ray32, SplitMix64};
use ch11::wide::scalar_boxes;
use ch11::{CompressedNode, FastRay, WideNode};
use raystep_core::glam::Vec3;

/// A random node of `W` boxes around `centre`, about `size` wide; slot
/// `empty` (if any) left empty.
fn node<const W: usize>(
    random: &mut SplitMix64, centre: f32, size: f32, empty: Option<usize>,
) -> WideNode<W> {
    let mut node = WideNode {
        lo: [[f32::INFINITY; W]; 3],
        hi: [[f32::NEG_INFINITY; W]; 3],
        child: [0; W],
        count: [1; W],
    };
    for i in 0..W {
        if Some(i) == empty {
            continue;
        }
        for axis in 0..3 {
            let a = centre + size * (random.next_f64() as f32 - 0.5);
            let b = a + size * 0.5 * random.next_f64() as f32;
            node.lo[axis][i] = a;
            node.hi[axis][i] = b;
        }
    }
    node
}

/// A random ray near the node: some directions with zero (±0)
/// components, some origins exactly on a box's plane.
fn ray<const W: usize>(
    random: &mut SplitMix64, node: &WideNode<W>, centre: f32, size: f32,
) -> Ray32 {
    let mut origin = Vec3::from_array(
        [0; 3].map(|_| centre + 2.0 * size * (random.next_f64() as f32 - 0.5)),
    );
    let mut direction = random.unit_vector().as_vec3();
    match random.next_u64() % 4 {
        0 => direction.x = 0.0,
        1 => direction.y = -0.0,
        2 => origin.z = node.lo[2][0],
        _ => {}
    }
    if random.next_u64().is_multiple_of(8) {
        origin.x = node.hi[0][0];
        direction.x = 0.0;
    }
    Ray32 { origin, direction }
}

#[cfg(target_arch = "x86_64")]
#[test]
fn sse_and_scalar_agree() {
    let mut random = SplitMix64::new(5);
    let mut tested = 0;
    for k in 0..4000 {
        let (centre, size) =
            ([0.0, 1e3, -1e7][k % 3], [1e-3, 1.0, 100.0][k % 3]);
        let empty = (k % 5 == 0).then_some(k % 4);
        let node: WideNode<4> = node(&mut random, centre, size, empty);
        let Some(ray) =
            FastRay::new(&ray(&mut random, &node, centre, size), false)
        else {
            continue;
        };
        for span in [(0.0, f32::INFINITY), (0.0, size), (size, 2.0 * size)] {
            let (t_scalar, hit_scalar) = scalar_boxes(&node, &ray, span);
            let (t_sse, hit_sse) = ch11::simd4::boxes4(&node, &ray, span);
            assert_eq!(hit_sse, hit_scalar, "case {k}");
            for i in 0..4 {
                if hit_scalar >> i & 1 == 1 {
                    assert_eq!(t_sse[i], t_scalar[i], "case {k}, box {i}");
                }
            }
            tested += 1;
        }
    }
    assert!(tested > 10_000, "{tested}");
}

#[cfg(target_arch = "x86_64")]
#[test]
fn avx_avx2_and_scalar_agree() {
    use ch11::compressed::scalar_boxes as compressed_scalar;
    use ch11::simd8::{
        boxes8_where_available, compressed_boxes8_where_available,
    };
    let mut random = SplitMix64::new(6);
    let mut tested = 0;
    for k in 0..4000 {
        let (centre, size) =
            ([0.0, 1e3, -1e7][k % 3], [1e-3, 1.0, 100.0][k % 3]);
        let empty = (k % 5 == 0).then_some(k % 8);
        let node: WideNode<8> = node(&mut random, centre, size, empty);
        let compressed = CompressedNode::new(&node);
        let Some(ray) =
            FastRay::new(&ray(&mut random, &node, centre, size), false)
        else {
            continue;
        };
        for span in [(0.0, f32::INFINITY), (0.0, size), (size, 2.0 * size)] {
            let pairs = [
                (
                    scalar_boxes(&node, &ray, span),
                    boxes8_where_available(&node, &ray, span),
                ),
                (
                    compressed_scalar(&compressed, &ray, span),
                    compressed_boxes8_where_available(&compressed, &ray, span),
                ),
            ];
            for ((t_scalar, hit_scalar), simd) in pairs {
                let Some((t_simd, hit_simd)) = simd else {
                    continue; // no AVX here: nothing to compare
                };
                assert_eq!(hit_simd, hit_scalar, "case {k}");
                for i in 0..8 {
                    if hit_scalar >> i & 1 == 1 {
                        assert_eq!(t_simd[i], t_scalar[i], "case {k}, box {i}");
                    }
                }
                tested += 1;
            }
        }
    }
    // where the CPU has AVX2 (it has AVX then too), every case compared
    if ch11::simd8::available_avx2() {
        assert!(tested > 20_000, "{tested}");
    }
}

/// The exact slab test in `f64` (the products of `f32`s nearly exact): does
/// the ray meet box `i` of `node` within `(t_min, t_max)`?
fn meets_exactly(
    node: &WideNode<8>, i: usize, ray: &Ray32, (t_min, t_max): (f32, f32),
) -> bool {
    let (mut near, mut far) = (f64::from(t_min), f64::from(t_max));
    for axis in 0..3 {
        let (lo, hi) =
            (f64::from(node.lo[axis][i]), f64::from(node.hi[axis][i]));
        let (o, d) =
            (f64::from(ray.origin[axis]), f64::from(ray.direction[axis]));
        if lo > hi {
            return false; // an empty slot
        }
        if d == 0.0 {
            if o < lo || o > hi {
                return false;
            }
            continue;
        }
        let (a, b) = ((lo - o) / d, (hi - o) / d);
        near = near.max(a.min(b));
        far = far.min(a.max(b));
    }
    near <= far
}

#[cfg(target_arch = "x86_64")]
#[test]
fn the_short_path_meets_every_box_the_ray_meets() {
    // step 11 folds the exit's widening into the reciprocal: other
    // roundings than step 5's, but never a box lost, and the same entry t
    use ch11::ray::WIDEN;
    use ch11::short_path::boxes_where_available;
    let mut random = SplitMix64::new(11);
    let (mut tested, mut met, mut differ) = (0, 0, 0);
    for k in 0..4000 {
        let (centre, size) =
            ([0.0, 1e3, -1e7][k % 3], [1e-3, 1.0, 100.0][k % 3]);
        let empty = (k % 5 == 0).then_some(k % 8);
        let node: WideNode<8> = node(&mut random, centre, size, empty);
        let mut ray32 = ray(&mut random, &node, centre, size);
        if k % 2 == 0 {
            // aimed at box 2: a point inside it, or (grazing) a corner
            let corner = k % 4 == 0;
            let target = Vec3::from_array([0, 1, 2].map(|axis| {
                let (lo, hi) = (node.lo[axis][2], node.hi[axis][2]);
                let f = if corner {
                    1.0
                } else {
                    random.next_f64() as f32
                };
                lo + f * (hi - lo)
            }));
            ray32.direction = (target - ray32.origin).normalize_or_zero();
        }
        let Some(ray) = FastRay::new(&ray32, false) else {
            continue;
        };
        for span in [(0.0, f32::INFINITY), (0.0, size), (size, 2.0 * size)] {
            // the span as the walks give it: its end widened
            let widened = (span.0, span.1 * WIDEN);
            let Some((t, hit)) = boxes_where_available(&node, &ray, widened)
            else {
                return; // no AVX here
            };
            let (t_scalar, hit_scalar) = scalar_boxes(&node, &ray, widened);
            for i in 0..8 {
                if meets_exactly(&node, i, &ray32, span) {
                    assert!(hit >> i & 1 == 1, "case {k}, box {i}: lost");
                    met += 1;
                }
                if hit >> i & 1 == 1 && hit_scalar >> i & 1 == 1 {
                    assert_eq!(t[i], t_scalar[i], "case {k}, box {i}");
                }
            }
            differ += (hit ^ hit_scalar).count_ones();
            tested += 1;
        }
    }
    assert!(tested > 10_000 && met > 5000, "{tested} cases, {met} met");
    // the two roundings disagree only on boxes the ray grazes
    assert!(differ < 20, "{differ} boxes differ from step 5's test");
}

#[test]
fn compressed_boxes_contain_the_originals() {
    let mut random = SplitMix64::new(9);
    for k in 0..3000 {
        let size = 10f32.powi((k % 14) as i32 - 6);
        let centre = [0.0, 1.0, -3e3, 1e7][k % 4];
        let empty = (k % 3 == 0).then_some(k % 8);
        let node: WideNode<8> = node(&mut random, centre, size, empty);
        let q = CompressedNode::new(&node);
        for i in 0..8 {
            let exists = Some(i) != empty;
            assert_eq!(q.valid >> i & 1 == 1, exists, "case {k}");
            if !exists {
                continue;
            }
            let [lo, hi] = q.decoded(i);
            for axis in 0..3 {
                assert!(lo[axis] <= node.lo[axis][i], "case {k}: {lo:?}");
                assert!(hi[axis] >= node.hi[axis][i], "case {k}: {hi:?}");
                // exact: the f32 sum is the real one
                let s = 2f64.powi(i32::from(q.exponent[axis]));
                let real =
                    f64::from(q.qlo[axis][i]) * s + f64::from(q.origin[axis]);
                assert_eq!(f64::from(lo[axis]), real, "case {k}");
            }
        }
    }
}

#[test]
fn compressed_boxes_stay_tight_for_boxes_of_similar_size() {
    // the point of compressing: children of a node are not much smaller
    // than the node, and then a byte per plane loses little
    let mut random = SplitMix64::new(3);
    let mut growth: f64 = 0.0;
    for _ in 0..500 {
        let node: WideNode<8> = node(&mut random, 0.3, 0.1, None);
        let q = CompressedNode::new(&node);
        for i in 0..8 {
            let [lo, hi] = q.decoded(i);
            for axis in 0..3 {
                let width = f64::from(node.hi[axis][i] - node.lo[axis][i]);
                let grown = f64::from(hi[axis] - lo[axis]) - width;
                growth = growth.max(grown / 0.1);
            }
        }
    }
    // two lattice steps of a node 0.15 wide at most: ≤ 2 · 2⁻⁸ of it
    assert!(growth < 0.02, "boxes grew by {growth} of the node's size");
}

#[test]
fn the_inlined_test_is_chapter_8s_bit_for_bit() {
    // rays at random points, and exactly at corners and edge midpoints
    // (where the fast edge function is unsure and chapter 8's exact one
    // decides), over triangles large, tiny, far away and edge-on
    let mut random = SplitMix64::new(21);
    let mut hits = 0;
    let mut cases = 0;
    let mut simd_cases = 0;
    for k in 0..20_000 {
        let scale = [1.0, 1e-4, 1e3][k % 3];
        let offset = [0.0, 1e5, -7.0][k % 3];
        let corner = |random: &mut SplitMix64| {
            let p = random.unit_vector() * scale + offset;
            p.as_vec3().as_dvec3() // exactly f32s, as a mesh's
        };
        let v = [
            corner(&mut random),
            corner(&mut random),
            corner(&mut random),
        ];
        let target = match k % 4 {
            0 => v[k % 3],
            1 => 0.5 * (v[0] + v[1]),
            _ => {
                let (a, b) = (random.next_f64(), random.next_f64());
                v[0] + a * (v[1] - v[0]) + b * (1.0 - a) * (v[2] - v[0])
            }
        };
        let eye = target + random.unit_vector() * 3.0 * scale;
        let ray = Ray32 {
            origin: eye.as_vec3(),
            direction: (target - eye).as_vec3(),
        };
        let Some(fast) = FastRay::new(&ray, false) else {
            continue;
        };
        let interval = raystep_core::Interval::new(0.0, f64::INFINITY);
        let ours = ch11::leaf_triangles::watertight(&v, &fast, interval);
        let theirs = ch08::watertight(&v, &ray.to_ray(), interval);
        assert_eq!(
            ours.map(f64::to_bits),
            theirs.map(f64::to_bits),
            "case {k}"
        );
        // step 6's test, three edges at once (where the CPU has AVX2)
        simd_cases += usize::from(three_edges_at_once(&v, &fast, theirs, k));
        // step 8's, four triangles at once
        four_at_once(&v, &fast, theirs, k);
        hits += usize::from(ours.is_some());
        cases += 1;
    }
    assert!(cases > 19_000 && hits > 5_000, "{cases} cases, {hits} hits");
    if simd_cases == 0 {
        eprintln!("no AVX2 here: step 6's test not compared");
    } else {
        assert_eq!(simd_cases, cases);
    }
}

#[test]
fn a_ray_in_the_triangles_plane_is_a_miss_in_every_kernel() {
    // small integer corners and rays lying exactly in the triangle's plane,
    // crossing its inside: the shear rounds, det comes out as noise, and
    // chapter 8 calls it 0 (no hit); the inlined test and step 6's must
    // do the same, from the same bound
    let v3 = raystep_core::DVec3::new;
    let planes = [
        (v3(1.0, -2.0, 3.0), v3(3.0, 1.0, -2.0), v3(-1.0, 2.0, 1.0)),
        (v3(-5.0, 4.0, 7.0), v3(7.0, 3.0, 5.0), v3(2.0, -6.0, 3.0)),
        (v3(0.0, 0.0, 0.0), v3(6.0, 0.0, 1.0), v3(0.0, 6.0, 5.0)),
    ];
    let interval = raystep_core::Interval::UNIVERSE;
    let mut cases = 0;
    for (corner, e1, e2) in planes {
        let v = [corner, corner + e1, corner + e2];
        for (a, b) in (-3..=3).flat_map(|a| (-3..=3).map(move |b| (a, b))) {
            let (a, b) = (f64::from(a), f64::from(b));
            let d = (1.0 - 4.0 * a) * e1 + (1.0 - 4.0 * b) * e2;
            let ray = Ray32 {
                origin: (corner + a * e1 + b * e2).as_vec3(),
                direction: d.as_vec3(),
            };
            let Some(fast) = FastRay::new(&ray, false) else {
                continue;
            };
            let theirs = ch08::watertight(&v, &ray.to_ray(), interval);
            assert_eq!(theirs, None, "{ray:?} lies in the plane of {v:?}");
            let ours = ch11::leaf_triangles::watertight(&v, &fast, interval);
            assert_eq!(ours, None, "{ray:?}, inlined");
            three_edges_at_once(&v, &fast, theirs, cases);
            four_at_once(&v, &fast, theirs, cases);
            cases += 1;
        }
    }
    assert!(cases > 100, "{cases} cases");
}

/// Step 6's test of `v` gives chapter 8's answer `theirs` bit for bit
/// (asserted); false where the CPU has no AVX2 (not compared).
#[cfg(target_arch = "x86_64")]
fn three_edges_at_once(
    v: &[raystep_core::DVec3; 3], ray: &FastRay, theirs: Option<f64>,
    case: usize,
) -> bool {
    use ch11::simd_triangle::{TriangleLanes, watertight_lanes};
    let corners: [f32; 9] = std::array::from_fn(|i| v[i / 3][i % 3] as f32);
    let Some(lanes) = TriangleLanes::new(&corners) else {
        return false;
    };
    assert_eq!(&lanes.corners(), v, "case {case}");
    let interval = raystep_core::Interval::new(0.0, f64::INFINITY);
    let ours = watertight_lanes(&lanes, ray, interval);
    assert_eq!(
        ours.map(f64::to_bits),
        theirs.map(f64::to_bits),
        "case {case}, three edges at once"
    );
    true
}

#[cfg(not(target_arch = "x86_64"))]
fn three_edges_at_once(
    _: &[raystep_core::DVec3; 3], _: &FastRay, _: Option<f64>, _: usize,
) -> bool {
    false
}

/// Step 8's test of a block holding `v` in lane `case % 4` (and three
/// other triangles): that lane, as its leaf takes it, gives chapter 8's
/// answer `theirs` bit for bit; and the AVX2 kernel (where the CPU has
/// it) says what the lane-by-lane test says of every lane, bit for bit.
fn four_at_once(
    v: &[raystep_core::DVec3; 3], ray: &FastRay, theirs: Option<f64>,
    case: usize,
) {
    use ch11::leaf4::{Lane, Triangle4, test4_scalar, test4_where_available};
    let centre = (v[0] + v[1] + v[2]) / 3.0;
    let others = [
        [v[0], v[2], v[1]],
        v.map(|p| centre + 1.5 * (p - centre)),
        v.map(|p| p + (v[1] - v[0]) * 0.25),
    ];
    let lane = case % 4;
    let mut block = Triangle4 {
        rows: [[[0.0; 4]; 3]; 3],
        ids: [0, 1, 2, 3],
    };
    let mut k = 0;
    for i in 0..4 {
        let triangle = if i == lane {
            *v
        } else {
            k += 1;
            others[k - 1]
        };
        for (c, corner) in triangle.iter().enumerate() {
            for axis in 0..3 {
                block.rows[c][axis][i] = corner[axis] as f32;
            }
        }
    }
    assert_eq!(&block.corners(lane), v, "case {case}");
    let interval = raystep_core::Interval::new(0.0, f64::INFINITY);
    let resolve = |answer: Lane, i: usize| match answer {
        Lane::Miss => None,
        Lane::Unsure => ch08::PreparedRay::new(&ray.ray)
            .triangle(&block.corners(i), interval),
        Lane::Hit(t) => interval.contains(t).then_some(t),
    };
    let scalar = test4_scalar(&block, ray);
    assert_eq!(
        resolve(scalar.lane(lane), lane).map(f64::to_bits),
        theirs.map(f64::to_bits),
        "case {case}, four at once, lane by lane"
    );
    let bits = |l: Lane| match l {
        Lane::Hit(t) => Some(t.to_bits()),
        Lane::Miss => None,
        Lane::Unsure => Some(u64::MAX),
    };
    if let Some(simd) = test4_where_available(&block, ray) {
        for i in 0..4 {
            assert_eq!(
                bits(simd.lane(i)),
                bits(scalar.lane(i)),
                "case {case}, lane {i}: AVX2 against lane by lane"
            );
        }
    }
    // Step 10: the block beside another (its lanes reversed), eight
    // lanes at once with AVX-512 where the CPU has it, each block's
    // lanes as the lane-by-lane test says, bit for bit.
    let mut reversed = block;
    for row in reversed.rows.iter_mut().flatten() {
        row.reverse();
    }
    let pair = [&block, &reversed];
    #[cfg(target_arch = "x86_64")]
    if let Some(tested) = ch11::pairs512::test8_where_available(pair, ray) {
        for (k, one) in pair.into_iter().enumerate() {
            let scalar = test4_scalar(one, ray);
            for i in 0..4 {
                assert_eq!(
                    bits(tested[k].lane(i)),
                    bits(scalar.lane(i)),
                    "case {case}, block {k}, lane {i}: AVX-512 against \
                     lane by lane"
                );
            }
        }
    }
    let _ = pair;
}
