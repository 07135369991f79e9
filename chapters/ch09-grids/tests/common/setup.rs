//! The DDA's setup as the lecture's steps define it, to judge a setup by:
//! exercise 1's property test checks any grid with it, and exercise 2's
//! tests check the setup each of their walks starts from, so that a fault
//! in exercise 1 is reported as one and not blamed on the walk; and any
//! grid, for both exercises' property tests.
use ch09::{Aabb, DVec3, Dda, Interval, Lattice, Ray};
use proptest::prelude::*;

/// What is wrong with `got` as the setup of `ray` within `interval`
/// (`expected …, got …`), or None if it is right (t values to rounding).
pub fn setup_fault(
    lattice: &Lattice, ray: &Ray, interval: Interval, got: Option<&Dda>,
) -> Option<String> {
    // Step 1: the box clips the ray.
    let (inside, got) =
        match (ch08::slab_test(&lattice.bounds, ray, interval), got) {
            (None, None) => return None,
            (None, Some(_)) => {
                return Some(
                    "expected None (the ray misses the grid's box within its \
                 interval), got a setup"
                        .to_string(),
                );
            }
            (Some(inside), None) => {
                return Some(format!(
                    "expected a setup (the ray is inside the grid's box for t \
                 in [{}, {}]), got None",
                    inside.min, inside.max
                ));
            }
            (Some(inside), Some(got)) => (inside, got),
        };
    if (got.t_enter, got.t_exit) != (inside.min, inside.max) {
        return Some(format!(
            "(t_enter, t_exit) expected ({}, {}) (where the ray is inside the \
             grid's box and its interval), got ({}, {})",
            inside.min, inside.max, got.t_enter, got.t_exit
        ));
    }
    // Step 2: the first cell holds the entry point.
    let entry = ray.at(inside.min);
    let cell = lattice.cell_of(entry);
    if got.cell != cell {
        return Some(format!(
            "cell expected {cell:?} (the cell holding the entry point \
             {entry}), got {:?}",
            got.cell
        ));
    }
    // Step 3: per axis, the step, the next plane's t and the t per cell.
    for (axis, name) in ["x", "y", "z"].into_iter().enumerate() {
        let d = ray.direction[axis];
        let o = ray.origin[axis];
        let size = lattice.size[axis];
        let (step, plane) = if d > 0.0 {
            (1, Some(lattice.plane(axis, cell[axis] + 1)))
        } else if d < 0.0 {
            (-1, Some(lattice.plane(axis, cell[axis])))
        } else {
            (0, None)
        };
        if got.step[axis] != step {
            return Some(format!(
                "step[{axis}] expected {step} (d.{name} = {d}), got {}",
                got.step[axis]
            ));
        }
        let (t_max, t_delta, why_max, why_delta) = match plane {
            Some(plane) => (
                (plane - o) / d,
                size / d.abs(),
                format!("the plane {name} = {plane}, from {name} = {o}"),
                format!("a cell {size} wide in {name}, d.{name} = {d}"),
            ),
            None => (
                f64::INFINITY,
                f64::INFINITY,
                format!("d.{name} = {d} never crosses a plane"),
                format!("d.{name} = {d} never crosses a plane"),
            ),
        };
        // A t found in another order may differ in its last bits.
        let scale = plane.map_or(0.0, |p| (p.abs() + o.abs()) / d.abs());
        if !close(got.t_max[axis], t_max, scale) {
            return Some(format!(
                "t_max.{name} expected {t_max} ({why_max}), got {}",
                got.t_max[axis]
            ));
        }
        if !close(got.t_delta[axis], t_delta, t_delta) {
            return Some(format!(
                "t_delta.{name} expected {t_delta} ({why_delta}), got {}",
                got.t_delta[axis]
            ));
        }
    }
    None
}

/// `got` is `expected` (NaN for NaN: a ray with a NaN origin), or within
/// 1e-12 of `scale` of it.
fn close(got: f64, expected: f64, scale: f64) -> bool {
    got == expected
        || (got.is_nan() && expected.is_nan())
        || (got - expected).abs() <= 1e-12 * scale
}

/// Any grid: its box anywhere in [−10, 10]³, 0.5 to 8 wide along each
/// axis, in 1 to 11 cells along each (so cells of any size and shape).
pub fn lattice_strategy() -> impl Strategy<Value = Lattice> {
    (
        prop::array::uniform3(-10.0..10.0f64),
        prop::array::uniform3(0.5..8.0f64),
        prop::array::uniform3(1usize..12),
    )
        .prop_map(|(min, size, cells)| {
            let min = DVec3::from(min);
            Lattice::new(Aabb::new(min, min + DVec3::from(size)), cells)
        })
}
