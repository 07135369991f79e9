//! Exercise 1: the DDA's setup. The first cell, and per axis the step,
//! the t of the next plane between cells and the t between two planes,
//! for hand-worked rays through a grid of unit cells, then through a grid
//! of 2 × 1.5 × 0.5 cells away from the origin, then through any grid.
mod common;

use std::fmt::Debug;

use ch09::{Aabb, DVec3, Dda, Interval, Lattice, Ray, dda_setup};
use common::setup::{lattice_strategy, setup_fault};
use proptest::prelude::*;
use raystep_check::{Table, num, seeded, vec3};

/// Fails with `what: expected …, got …` unless `got` is `expected`.
#[track_caller]
fn expect_eq<T: PartialEq + Debug>(what: &str, got: T, expected: T) {
    assert!(
        got == expected,
        "{what}: expected {expected:?}, got {got:?}"
    );
}

/// Fails with `what: expected …, got …` unless `got` is `expected` to
/// rounding (a t found in another order may differ in its last bits).
#[track_caller]
fn expect_close(what: &str, got: DVec3, expected: DVec3) {
    let close = (0..3).all(|a| {
        got[a] == expected[a]
            || (got[a] - expected[a]).abs() <= 1e-12 * expected[a].abs()
    });
    assert!(
        close,
        "{what}: expected {}, got {}",
        vec3(expected),
        vec3(got)
    );
}

/// The box [0, 4] × [0, 3] × [0, 2] in unit cells.
fn lattice() -> Lattice {
    Lattice::new(Aabb::new(DVec3::ZERO, DVec3::new(4.0, 3.0, 2.0)), [4, 3, 2])
}

fn ray(o: [f64; 3], d: [f64; 3]) -> Ray {
    Ray::new(DVec3::from(o), DVec3::from(d))
}

/// The cases: a name, the ray, its interval.
fn cases() -> Vec<(&'static str, Ray, Interval)> {
    let all = Interval::FORWARD;
    vec![
        (
            "along +x from outside",
            ray([-1.0, 0.5, 0.5], [1.0, 0.0, 0.0]),
            all,
        ),
        (
            "diagonal from inside",
            ray([0.5, 0.5, 0.5], [1.0, 2.0, 0.0]),
            all,
        ),
        (
            "toward -x -y -z",
            ray([3.5, 2.5, 1.5], [-1.0, -1.0, -1.0]),
            all,
        ),
        (
            "from a corner, up",
            ray([2.0, 1.0, 1.0], [1.0, 1.0, 1.0]),
            all,
        ),
        (
            "from a corner, down",
            ray([2.0, 1.0, 1.0], [-1.0, -1.0, -1.0]),
            all,
        ),
        ("d.y = -0.0", ray([0.5, 0.5, 0.5], [1.0, -0.0, 0.0]), all),
        (
            "misses the box",
            ray([-1.0, 5.0, 0.5], [1.0, 0.0, 0.0]),
            all,
        ),
        (
            "interval [2, 3]",
            ray([-1.0, 0.5, 0.5], [1.0, 0.0, 0.0]),
            Interval::new(2.0, 3.0),
        ),
        (
            "long direction",
            ray([-2.0, 0.5, 0.5], [4.0, 0.0, 1.0]),
            all,
        ),
    ]
}

fn cell(d: &Dda) -> String {
    format!("{} {} {}", d.cell[0], d.cell[1], d.cell[2])
}

fn three(v: DVec3) -> String {
    v.to_array().map(num).join(" ")
}

/// The setup of each of `cases` in `lattice`, one row each.
fn setup_table_of(
    lattice: &Lattice, cases: Vec<(&'static str, Ray, Interval)>,
) -> String {
    let mut table = Table::new(&[
        "ray", "cell", "step", "t_max", "t_delta", "t_enter", "t_exit",
    ]);
    for (name, ray, interval) in cases {
        match dda_setup(lattice, &ray, interval) {
            Some(d) => table.row(&[
                name.to_string(),
                cell(&d),
                format!("{} {} {}", d.step[0], d.step[1], d.step[2]),
                three(d.t_max),
                three(d.t_delta),
                num(d.t_enter),
                num(d.t_exit),
            ]),
            None => table.row(&[name, "none", "", "", "", "", ""]),
        };
    }
    table.to_string()
}

#[test]
fn setup_table() {
    insta::assert_snapshot!(setup_table_of(&lattice(), cases()));
}

/// The diagonal ray worked by hand: from (0.5, 0.5) along (1, 2) it meets
/// y = 1 at t = 0.25 and x = 1 at t = 0.5; a cell is 1 wide in x (t 1)
/// and 1 high in y (t 0.5); it never crosses a z plane.
#[test]
fn the_diagonal_by_hand() {
    let (_, ray, interval) = cases()[1];
    let d = dda_setup(&lattice(), &ray, interval);
    let d = d.expect("the diagonal starts inside the box: expected a setup");
    let what = "the diagonal from (0.5, 0.5, 0.5) along (1, 2, 0)";
    expect_eq(&format!("{what}: cell"), d.cell, [0, 0, 0]);
    expect_eq(&format!("{what}: step"), d.step, [1, 1, 0]);
    let t_max = DVec3::new(0.5, 0.25, f64::INFINITY);
    expect_close(&format!("{what}: t_max"), d.t_max, t_max);
    let t_delta = DVec3::new(1.0, 0.5, f64::INFINITY);
    expect_close(&format!("{what}: t_delta"), d.t_delta, t_delta);
    expect_eq(&format!("{what}: t_enter"), d.t_enter, 0.0);
}

/// Going toward −x, the next plane is the cell's own lower one; a ray
/// starting on a plane belongs to the cell above (the tie rule), so going
/// down it leaves that cell at once (t_max = 0).
#[test]
fn going_down_the_next_plane_is_the_cells_own() {
    let (_, ray, interval) = cases()[2];
    let d = dda_setup(&lattice(), &ray, interval);
    let d = d.expect("the ray starts inside the box: expected a setup");
    let what = "from (3.5, 2.5, 1.5) toward (-1, -1, -1)";
    expect_eq(&format!("{what}: cell"), d.cell, [3, 2, 1]);
    expect_eq(&format!("{what}: step"), d.step, [-1, -1, -1]);
    let t_max = DVec3::splat(0.5);
    expect_close(
        &format!("{what}: t_max (the cell's own planes)"),
        d.t_max,
        t_max,
    );
    expect_close(&format!("{what}: t_delta"), d.t_delta, DVec3::ONE);
    let (_, ray, interval) = cases()[4];
    let d = dda_setup(&lattice(), &ray, interval);
    let d = d.expect("the ray starts inside the box: expected a setup");
    let what = "from the corner (2, 1, 1) toward (-1, -1, -1)";
    expect_eq(
        &format!("{what}: cell (the one above each plane)"),
        d.cell,
        [2, 1, 1],
    );
    expect_close(
        &format!("{what}: t_max (the cell's own planes, at t 0)"),
        d.t_max,
        DVec3::ZERO,
    );
}

/// A zero component, +0.0 or −0.0, never crosses a plane: step 0 and
/// +∞, not −∞ and not NaN (0/0).
#[test]
fn a_parallel_axis_never_steps() {
    for y in [0.0, -0.0] {
        let r = ray([0.5, 1.0, 0.5], [1.0, y, 0.0]);
        let d = dda_setup(&lattice(), &r, Interval::FORWARD);
        let d = d.expect("the ray starts inside the box: expected a setup");
        let what = format!("from (0.5, 1, 0.5) along (1, {y:?}, 0)");
        expect_eq(&format!("{what}: step[1]"), d.step[1], 0);
        expect_eq(&format!("{what}: t_max.y"), d.t_max.y, f64::INFINITY);
        expect_eq(&format!("{what}: t_delta.y"), d.t_delta.y, f64::INFINITY);
        expect_eq(
            &format!("{what}: cell[1] (on the plane y = 1: the cell above)"),
            d.cell[1],
            1,
        );
    }
}

/// The box clips the ray, the interval clips the box: a ray that misses
/// the box, or meets it only outside the interval, has no setup.
#[test]
fn the_box_and_the_interval_clip_the_walk() {
    let r = ray([-1.0, 0.5, 0.5], [1.0, 0.0, 0.0]);
    let l = lattice();
    let what = "from (-1, 0.5, 0.5) along +x";
    let d = dda_setup(&l, &r, Interval::new(0.0, 0.5));
    expect_eq(
        &format!("{what} in t [0, 0.5] (it reaches the box at t 1)"),
        d,
        None,
    );
    let d = dda_setup(&l, &r, Interval::new(2.0, 3.0));
    let d = d.expect("along +x in t [2, 3], inside the box: expected a setup");
    expect_eq(
        &format!("{what} in t [2, 3]: (cell, t_enter, t_exit)"),
        (d.cell, d.t_enter, d.t_exit),
        ([1, 0, 0], 2.0, 3.0),
    );
    expect_eq(&format!("{what} in t [2, 3]: t_max.x"), d.t_max.x, 3.0);
    let (_, miss, interval) = cases()[6];
    let d = dda_setup(&l, &miss, interval);
    expect_eq("from (-1, 5, 0.5) along +x, above the box", d, None);
}

/// The box [−3, 5] × [1, 4] × [2, 2.5] in 4 × 2 × 1 cells of 2 × 1.5 × 0.5:
/// cells that are not unit cubes, in a grid away from the origin.
fn offset_lattice() -> Lattice {
    Lattice::new(
        Aabb::new(DVec3::new(-3.0, 1.0, 2.0), DVec3::new(5.0, 4.0, 2.5)),
        [4, 2, 1],
    )
}

/// The cases of the offset grid: a name, the ray, its interval.
fn offset_cases() -> Vec<(&'static str, Ray, Interval)> {
    let all = Interval::FORWARD;
    vec![
        (
            "along +x from outside",
            ray([-5.0, 1.75, 2.25], [1.0, 0.0, 0.0]),
            all,
        ),
        (
            "diagonal from inside",
            ray([0.0, 3.0, 2.25], [1.0, -1.5, 0.25]),
            all,
        ),
        (
            "toward -x -y from outside",
            ray([7.0, 4.25, 2.4], [-2.0, -1.0, 0.0]),
            all,
        ),
        (
            "interval [5, 6]",
            ray([-5.0, 1.75, 2.25], [1.0, 0.0, 0.0]),
            Interval::new(5.0, 6.0),
        ),
        (
            "on two planes, down",
            ray([1.0, 2.5, 2.25], [-1.0, -1.0, 0.0]),
            all,
        ),
        ("d.y = -0.0", ray([-1.0, 2.5, 2.25], [0.5, -0.0, 0.0]), all),
        (
            "misses the box",
            ray([-5.0, 0.5, 2.25], [1.0, 0.0, 0.0]),
            all,
        ),
    ]
}

/// Two rays through the offset grid worked by hand. A cell is 2 wide, 1.5
/// high and 0.5 deep, so t_delta = size / |d| per axis; its planes are at
/// x = −3, −1, 1, 3, 5, y = 1, 2.5, 4 and z = 2, 2.5: the box's min plus
/// the cell number times the size.
#[test]
fn cells_of_any_size_anywhere_by_hand() {
    let l = offset_lattice();
    // From (−5, 1.75, 2.25) along +x: it enters at x = −3 (t 2), in cell
    // 0 0 0, and leaves it through x = −1 at t 4; each cell takes t 2.
    let (_, ray, interval) = offset_cases()[0];
    let d = dda_setup(&l, &ray, interval);
    let d = d.expect("along +x into the offset grid: expected a setup");
    let what = "along +x into cells 2 × 1.5 × 0.5 from x = -3";
    expect_eq(&format!("{what}: cell"), d.cell, [0, 0, 0]);
    expect_eq(&format!("{what}: t_enter"), d.t_enter, 2.0);
    let t_max = DVec3::new(4.0, f64::INFINITY, f64::INFINITY);
    expect_close(&format!("{what}: t_max (the plane x = -1)"), d.t_max, t_max);
    let t_delta = DVec3::new(2.0, f64::INFINITY, f64::INFINITY);
    expect_close(
        &format!("{what}: t_delta (a cell 2 wide)"),
        d.t_delta,
        t_delta,
    );
    // From (0, 3, 2.25) along (1, −1.5, 0.25): cell 1 1 0; the next planes
    // are x = 1 (t 1), y = 2.5 below (t 1/3) and z = 2.5 (t 1).
    let (_, ray, interval) = offset_cases()[1];
    let d = dda_setup(&l, &ray, interval);
    let d = d.expect("the diagonal starts inside the box: expected a setup");
    let what = "from (0, 3, 2.25) along (1, -1.5, 0.25) in cells 2 × 1.5 × 0.5";
    expect_eq(&format!("{what}: cell"), d.cell, [1, 1, 0]);
    expect_eq(&format!("{what}: step"), d.step, [1, -1, 1]);
    let t_max = DVec3::new(1.0, 1.0 / 3.0, 1.0);
    expect_close(
        &format!("{what}: t_max (the planes x = 1, y = 2.5, z = 2.5)"),
        d.t_max,
        t_max,
    );
    let t_delta = DVec3::new(2.0, 1.0, 2.0);
    expect_close(&format!("{what}: t_delta (size / |d|)"), d.t_delta, t_delta);
}

#[test]
fn offset_setup_table() {
    insta::assert_snapshot!(setup_table_of(&offset_lattice(), offset_cases()));
}

proptest! {
    #![proptest_config(seeded(300))]

    /// For any grid (any size of cell, anywhere) and ray, in any
    /// interval: the setup the lecture's steps give.
    #[test]
    fn the_setup_on_any_grid(
        lattice in lattice_strategy(),
        origin in prop::array::uniform3(-20.0..20.0f64),
        direction in prop::array::uniform3(-1.0..1.0f64),
        axis_parallel in 0usize..4,
        t_min in prop_oneof![Just(0.0), 0.0..20.0f64],
        length in prop_oneof![Just(f64::INFINITY), 0.0..20.0f64],
    ) {
        let mut direction = DVec3::from(direction);
        if axis_parallel < 3 {
            // three rays in four parallel to one axis's planes
            direction[axis_parallel] = 0.0;
        }
        prop_assume!(direction.length() > 1e-3);
        let ray = Ray::new(DVec3::from(origin), direction);
        let interval = Interval::new(t_min, t_min + length);
        let got = dda_setup(&lattice, &ray, interval);
        let fault = setup_fault(&lattice, &ray, interval, got.as_ref());
        prop_assert!(
            fault.is_none(),
            "grid {} to {} in {:?} cells, ray from {} along {}, \
             t in [{}, {}]: {}",
            lattice.bounds.min, lattice.bounds.max, lattice.cells,
            ray.origin, ray.direction, interval.min, interval.max,
            fault.unwrap_or_default()
        );
    }
}
