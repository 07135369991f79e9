//! Exercise 2: the stepping loop. The cells come in order along the ray,
//! each a face-neighbour of the one before, each entered where the last
//! was left, and together they hold every point of the ray inside the
//! grid; the walk stops when told to, and always ends.
//!
//! The walk starts from exercise 1's `dda_setup`, the student's own in
//! student mode (the reference is not built then). So every walk here
//! first checks the setup it starts from against the lecture's steps
//! (`common::setup`), and a fault there fails the walk's test with "fails
//! because dda_setup fails: …": the message blames exercise 1, not the
//! loop.
mod common;

use std::ops::ControlFlow;

use ch09::{Aabb, DVec3, Interval, Lattice, Ray, Visit, dda_setup, walk};
use common::setup::{lattice_strategy, setup_fault};
use proptest::prelude::*;
use raystep_check::seeded;

/// Why the walk of `ray` cannot be judged: its setup (exercise 1) is
/// wrong. None if the setup is right.
fn setup_fails(
    lattice: &Lattice, ray: &Ray, interval: Interval,
) -> Option<String> {
    let got = dda_setup(lattice, ray, interval);
    let fault = setup_fault(lattice, ray, interval, got.as_ref())?;
    Some(format!(
        "fails because dda_setup fails: ray from {} along {}, t in [{}, \
         {}]: {fault}",
        ray.origin, ray.direction, interval.min, interval.max
    ))
}

/// Every cell `ray` visits within `interval`, once the setup the walk
/// starts from is checked; or why not: a wrong setup, or a walk that goes
/// on past all the cells a ray can cross (then it is stopped there).
fn walked(
    lattice: &Lattice, ray: &Ray, interval: Interval,
) -> Result<Vec<Visit>, String> {
    if let Some(why) = setup_fails(lattice, ray, interval) {
        return Err(why);
    }
    // A line crosses at most nx + ny + nz − 2 cells: past the sum, the
    // walk is endless (stop it, and say so).
    let most: usize = lattice.cells.iter().sum();
    let mut seen = Vec::new();
    walk(lattice, ray, interval, |v| {
        seen.push(v);
        if seen.len() > most {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    });
    if seen.len() > most {
        return Err(format!(
            "ray from {} along {}, t in [{}, {}]: expected at most {most} \
             cells (all a ray can cross in {:?} cells), got more: the walk \
             does not stop (the first {}: {})",
            ray.origin,
            ray.direction,
            interval.min,
            interval.max,
            lattice.cells,
            most + 1,
            listed(&seen)
        ));
    }
    Ok(seen)
}

/// [`walked`], or a panic that says why not.
#[track_caller]
fn visits(lattice: &Lattice, ray: &Ray, interval: Interval) -> Vec<Visit> {
    walked(lattice, ray, interval).unwrap_or_else(|why| panic!("{why}"))
}

/// The visits as text: `cell x y z, t in..out` each.
fn listed(seen: &[Visit]) -> String {
    let list: Vec<String> = seen
        .iter()
        .map(|v| {
            let [x, y, z] = v.cell;
            format!("{x} {y} {z}, t {}..{}", v.t_in, v.t_out)
        })
        .collect();
    format!("[{}]", list.join("; "))
}

/// A flat grid of 12 × 8 unit cells (one cell deep): the 2D picture.
fn flat() -> Lattice {
    Lattice::new(
        Aabb::new(DVec3::ZERO, DVec3::new(12.0, 8.0, 1.0)),
        [12, 8, 1],
    )
}

/// The visited cells of a flat grid as text, y up: each cell shows the
/// order in which the ray entered it (0–9, then a–z), `.` if it did not.
fn picture(lattice: &Lattice, rays: &[Ray]) -> String {
    let [w, h, _] = lattice.cells;
    let mut rows = vec![vec!['.'; w]; h];
    for ray in rays {
        for (k, v) in visits(lattice, ray, Interval::FORWARD).iter().enumerate()
        {
            let mark = char::from_digit(k as u32 % 36, 36).unwrap();
            let [x, y, z] = v.cell;
            assert!(
                x < w && y < h && z == 0,
                "visit {k}: expected a cell of the {w} × {h} × 1 grid, got \
                 cell {x} {y} {z}"
            );
            rows[y][x] = mark;
        }
    }
    rows.iter()
        .rev()
        .map(|r| r.iter().collect::<String>())
        .collect::<Vec<_>>()
        .join("\n")
}

fn ray(o: [f64; 3], d: [f64; 3]) -> Ray {
    Ray::new(DVec3::from(o), DVec3::from(d))
}

/// The lecture's picture: a shallow ray and a steep one, stepping from
/// cell to cell like a line drawn by a rasterizer, but through every
/// cell the line touches (a rasterized line takes one pixel a column).
#[test]
fn two_rays_through_a_flat_grid() {
    let rays = [
        ray([0.3, 0.6, 0.5], [1.0, 0.4, 0.0]),
        ray([11.5, 7.9, 0.5], [-0.35, -1.0, 0.0]),
    ];
    insta::assert_snapshot!(picture(&flat(), &rays[..1]));
    insta::assert_snapshot!(picture(&flat(), &rays[1..]));
}

/// Along the line x = 4 exactly (a plane between cells), the tie rule
/// puts the ray in the column to its right; through the corner (4, 4)
/// diagonally, it steps x first on the tie and never visits both
/// side cells.
#[test]
fn ties_on_lines_and_corners() {
    let up = visits(
        &flat(),
        &ray([4.0, -1.0, 0.5], [0.0, 1.0, 0.0]),
        Interval::FORWARD,
    );
    let columns: Vec<usize> = up.iter().map(|v| v.cell[0]).collect();
    assert!(
        columns == [4; 8],
        "up the line x = 4: expected the 8 cells of column 4 (a point on \
         a plane belongs to the cell above), got columns {columns:?}"
    );
    let diagonal = visits(
        &flat(),
        &ray([2.5, 2.5, 0.5], [1.0, 1.0, 0.0]),
        Interval::FORWARD,
    );
    let cells: Vec<[usize; 2]> =
        diagonal.iter().map(|v| [v.cell[0], v.cell[1]]).collect();
    let expected = [[2, 2], [3, 2], [3, 3], [4, 3], [4, 4]];
    assert!(
        cells.starts_with(&expected),
        "diagonally through the corners (3, 3) and (4, 4): expected the \
         cells {expected:?} first (x steps first on a tie), got {cells:?}"
    );
}

/// The interval can begin and end inside a cell: the first cell is
/// entered where the interval begins (t_enter), the last one left where it
/// ends (t_exit), not at the cell's far plane.
#[test]
fn the_interval_cuts_the_first_and_last_cells() {
    let seen = visits(
        &flat(),
        &ray([0.5, 0.5, 0.5], [1.0, 0.0, 0.0]),
        Interval::new(1.25, 2.25),
    );
    let cells: Vec<usize> = seen.iter().map(|v| v.cell[0]).collect();
    assert!(
        cells == [1, 2],
        "along +x from x = 0.5 in t [1.25, 2.25] (x 1.75 to 2.75): \
         expected the cells x = [1, 2], got x = {cells:?} ({})",
        listed(&seen)
    );
    let (first, last) = (seen[0], seen[1]);
    assert!(
        first.t_in == 1.25 && first.t_out == 1.5,
        "cell 1 0 0: expected t 1.25..1.5 (entered where the interval \
         begins, left at the plane x = 2), got t {}..{}",
        first.t_in,
        first.t_out
    );
    assert!(
        last.t_in == 1.5 && last.t_out == 2.25,
        "cell 2 0 0: expected t 1.5..2.25 (left where the interval ends, \
         t_out = min(t_max, t_exit)), got t {}..{}",
        last.t_in,
        last.t_out
    );
}

/// The visitor's Break ends the walk at once; a one-cell grid is one
/// visit; rays that are not rays (NaN, zero direction) end, after no
/// more cells than a ray could cross.
#[test]
fn the_walk_stops() {
    let mut count = 0;
    let along_x = ray([0.5, 0.5, 0.5], [1.0, 0.0, 0.0]);
    if let Some(why) = setup_fails(&flat(), &along_x, Interval::FORWARD) {
        panic!("{why}");
    }
    walk(&flat(), &along_x, Interval::FORWARD, |_| {
        count += 1;
        if count == 3 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    });
    assert!(
        count == 3,
        "a visitor that breaks at its 3rd cell: expected 3 visits, got \
         {count}"
    );
    let one = Lattice::new(Aabb::new(DVec3::ZERO, DVec3::ONE), [1, 1, 1]);
    let v = visits(
        &one,
        &ray([-1.0, 0.5, 0.5], [1.0, 0.1, 0.0]),
        Interval::FORWARD,
    );
    assert!(
        v.len() == 1 && (v[0].t_in, v[0].cell) == (1.0, [0, 0, 0]),
        "through a one-cell grid from x = -1 along +x: expected cell 0 0 \
         0 entered at t 1, got {}",
        listed(&v)
    );
    for broken in [
        ray([0.5, 0.5, 0.5], [0.0, 0.0, 0.0]),
        ray([0.5, 0.5, 0.5], [f64::NAN, 1.0, 0.0]),
        ray([f64::NAN, 0.5, 0.5], [1.0, 0.0, 0.0]),
    ] {
        // `visits` fails past all the cells a ray can cross
        visits(&flat(), &broken, Interval::FORWARD);
    }
}

proptest! {
    #![proptest_config(seeded(300))]

    /// For any grid and ray: the cells are face-neighbours in order along
    /// the ray, each entered where the last was left, and every point of
    /// the ray inside the grid (sampled) lies in a visited cell; the walk
    /// begins where the ray enters the grid and ends where it leaves.
    #[test]
    fn the_walk_covers_the_ray(
        lattice in lattice_strategy(),
        origin in prop::array::uniform3(-20.0..20.0f64),
        direction in prop::array::uniform3(-1.0..1.0f64),
        axis_parallel in 0usize..4,
    ) {
        let mut direction = DVec3::from(direction);
        if axis_parallel < 3 {
            // three rays in four parallel to two axes' planes
            direction = DVec3::ZERO;
            direction[axis_parallel] = 1.0;
        }
        prop_assume!(direction.length() > 1e-3);
        let ray = Ray::new(DVec3::from(origin), direction);
        let interval = Interval::FORWARD;
        let seen = walked(&lattice, &ray, interval);
        let seen = seen.map_err(TestCaseError::fail)?;
        let case = format!(
            "grid {} to {} in {:?} cells, ray from {} along {}",
            lattice.bounds.min, lattice.bounds.max, lattice.cells,
            ray.origin, ray.direction
        );
        for (k, v) in seen.iter().enumerate() {
            prop_assert!(
                (0..3).all(|a| v.cell[a] < lattice.cells[a])
                    && v.index == lattice.index(v.cell),
                "{}: visit {}: expected a cell of the grid and its index, \
                 got cell {:?}, index {} (the cell's is {})",
                case, k, v.cell, v.index, lattice.index(v.cell)
            );
        }
        for (k, pair) in seen.windows(2).enumerate() {
            let steps: usize = (0..3)
                .map(|a| pair[0].cell[a].abs_diff(pair[1].cell[a]))
                .sum();
            prop_assert!(
                steps == 1,
                "{}: visits {} and {}: expected face-neighbours, got cells \
                 {:?} then {:?}",
                case, k, k + 1, pair[0].cell, pair[1].cell
            );
            prop_assert!(
                pair[0].t_out == pair[1].t_in,
                "{}: visits {} and {}: expected the next cell entered where \
                 the last was left (t {}), got t {}",
                case, k, k + 1, pair[0].t_out, pair[1].t_in
            );
        }
        for (k, v) in seen.iter().enumerate() {
            prop_assert!(
                v.t_in <= v.t_out,
                "{}: visit {}: expected t_in <= t_out, got t {}..{}",
                case, k, v.t_in, v.t_out
            );
        }
        let Some(inside) = ch08::slab_test(&lattice.bounds, &ray, interval) else {
            prop_assert!(
                seen.is_empty(),
                "{}: the ray misses the grid: expected no cells, got {}",
                case, listed(&seen)
            );
            return Ok(());
        };
        let (Some(first), Some(last)) = (seen.first(), seen.last()) else {
            return Err(TestCaseError::fail(format!(
                "{case}: the ray is inside the grid for t in [{}, {}]: \
                 expected cells, got none",
                inside.min, inside.max
            )));
        };
        prop_assert!(
            first.t_in == inside.min,
            "{}: expected the first cell entered at t {} (where the ray \
             enters the grid), got t {}",
            case, inside.min, first.t_in
        );
        prop_assert!(
            last.t_out <= inside.max,
            "{}: expected the last cell left by t {} (where the ray leaves \
             the grid), got t {}",
            case, inside.max, last.t_out
        );
        for k in 0..=200 {
            let t = inside.min
                + (inside.max - inside.min) * f64::from(k) / 200.0;
            let p = ray.at(t);
            // a sample on a plane may belong to either neighbour
            let near_plane = (0..3).any(|a| {
                let x = (p[a] - lattice.bounds.min[a]) / lattice.size[a];
                (x - x.round()).abs() < 1e-9
            });
            let cell = lattice.cell_of(p);
            prop_assert!(
                near_plane || seen.iter().any(|v| v.cell == cell),
                "{}: expected every point inside the grid in a visited \
                 cell, got t = {} at {} in cell {:?}, not visited",
                case, t, p, cell
            );
        }
    }
}
