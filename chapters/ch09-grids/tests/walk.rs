//! Exercise 2: the stepping loop. The cells come in order along the ray,
//! each a face-neighbour of the one before, each entered where the last
//! was left, and together they hold every point of the ray inside the
//! grid; the walk stops when told to, and always ends.
use std::ops::ControlFlow;

use ch09::{Aabb, DVec3, Interval, Lattice, Ray, Visit, walk};
use proptest::prelude::*;
use raystep_check::seeded;

/// Every cell `ray` visits within `interval`.
fn visits(lattice: &Lattice, ray: &Ray, interval: Interval) -> Vec<Visit> {
    let mut seen = Vec::new();
    walk(lattice, ray, interval, |v| {
        seen.push(v);
        ControlFlow::Continue(())
    });
    seen
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
            rows[v.cell[1]][v.cell[0]] = mark;
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
    assert_eq!(up.len(), 8);
    assert!(up.iter().all(|v| v.cell[0] == 4), "{up:?}");
    let diagonal = visits(
        &flat(),
        &ray([2.5, 2.5, 0.5], [1.0, 1.0, 0.0]),
        Interval::FORWARD,
    );
    let cells: Vec<[usize; 2]> =
        diagonal.iter().map(|v| [v.cell[0], v.cell[1]]).collect();
    assert_eq!(
        &cells[..5],
        &[[2, 2], [3, 2], [3, 3], [4, 3], [4, 4]],
        "x steps first on a tie"
    );
}

/// The visitor's Break ends the walk at once; a one-cell grid is one
/// visit; rays that are not rays (NaN, zero direction) end, after no
/// more cells than a ray could cross.
#[test]
fn the_walk_stops() {
    let mut count = 0;
    walk(
        &flat(),
        &ray([0.5, 0.5, 0.5], [1.0, 0.0, 0.0]),
        Interval::FORWARD,
        |_| {
            count += 1;
            if count == 3 {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        },
    );
    assert_eq!(count, 3);
    let one = Lattice::new(Aabb::new(DVec3::ZERO, DVec3::ONE), [1, 1, 1]);
    let v = visits(
        &one,
        &ray([-1.0, 0.5, 0.5], [1.0, 0.1, 0.0]),
        Interval::FORWARD,
    );
    assert_eq!(v.len(), 1);
    assert_eq!((v[0].t_in, v[0].cell), (1.0, [0, 0, 0]));
    for broken in [
        ray([0.5, 0.5, 0.5], [0.0, 0.0, 0.0]),
        ray([0.5, 0.5, 0.5], [f64::NAN, 1.0, 0.0]),
        ray([f64::NAN, 0.5, 0.5], [1.0, 0.0, 0.0]),
    ] {
        assert!(visits(&flat(), &broken, Interval::FORWARD).len() <= 12 + 8);
    }
}

fn lattice_strategy() -> impl Strategy<Value = Lattice> {
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

proptest! {
    #![proptest_config(seeded(300))]

    /// For any grid and ray: the cells are face-neighbours in order along
    /// the ray, each entered where the last was left, and every point of
    /// the ray inside the grid (sampled) lies in a visited cell.
    #[test]
    fn the_walk_covers_the_ray(
        lattice in lattice_strategy(),
        origin in prop::array::uniform3(-20.0..20.0f64),
        direction in prop::array::uniform3(-1.0..1.0f64),
        axis_parallel in 0usize..4,
    ) {
        let mut direction = DVec3::from(direction);
        if axis_parallel < 3 {
            // a third of the rays parallel to two axes' planes
            direction = DVec3::ZERO;
            direction[axis_parallel] = 1.0;
        }
        prop_assume!(direction.length() > 1e-3);
        let ray = Ray::new(DVec3::from(origin), direction);
        let seen = visits(&lattice, &ray, Interval::FORWARD);
        for pair in seen.windows(2) {
            let steps: usize = (0..3)
                .map(|a| pair[0].cell[a].abs_diff(pair[1].cell[a]))
                .sum();
            prop_assert_eq!(steps, 1, "not a face-neighbour: {:?}", pair);
            prop_assert_eq!(pair[0].t_out, pair[1].t_in);
            prop_assert!(pair[0].t_in <= pair[0].t_out);
        }
        let Some(inside) = lattice.bounds.hit(&ray, Interval::FORWARD) else {
            prop_assert!(seen.is_empty());
            return Ok(());
        };
        prop_assert!(!seen.is_empty());
        for k in 0..=200 {
            let t = inside.min + (inside.max - inside.min) * f64::from(k) / 200.0;
            let p = ray.at(t);
            // a sample on a plane may belong to either neighbour
            let near_plane = (0..3).any(|a| {
                let x = (p[a] - lattice.bounds.min[a]) / lattice.size[a];
                (x - x.round()).abs() < 1e-9
            });
            let cell = lattice.cell_of(p);
            prop_assert!(
                near_plane || seen.iter().any(|v| v.cell == cell),
                "t = {} at {} in cell {:?}, not visited", t, p, cell
            );
        }
    }
}
