//! The grid itself: how many cells the rule chooses, which cells list an
//! object (by its box, or exactly), what stays outside, and what it all
//! costs in entries and bytes. No exercise needed.
mod common;

use ch09::{
    Aabb, DVec3, Fill, Grid, Lattice, Resolution, cells_for, rule_cells,
    triangle_overlaps_box,
};
use raystep_bench::{SCENE_SEED, bunny, stadium, uniform_triangles};
use raystep_check::Table;
use raystep_check::held_out::Rng;

use common::{plane_object, sphere_objects};

/// The rule (3·∛N along the longest axis) and the grid it gives, for the
/// chapter's scenes.
#[test]
fn the_rule_on_the_chapters_scenes() {
    let mut table = Table::new(&[
        "scene",
        "triangles",
        "rule",
        "cells",
        "entries (boxes)",
        "entries (exact)",
        "empty cells",
        "longest list",
    ]);
    let bunny = bunny();
    let scenes = [
        ("uniform, 10 000", uniform_triangles(10_000, SCENE_SEED)),
        ("bunny", bunny.clone()),
        ("bunny in a stadium", stadium(&bunny)),
    ];
    for (name, triangles) in scenes {
        let boxes =
            Grid::for_triangles(&triangles, Resolution::Rule, Fill::Boxes);
        let exact =
            Grid::for_triangles(&triangles, Resolution::Rule, Fill::Exact);
        let (b, e) = (boxes.stats(), exact.stats());
        assert_eq!(b.cells, e.cells);
        assert!(e.entries <= b.entries, "{name}: exact lists more");
        table.row(&[
            name.to_string(),
            triangles.len().to_string(),
            rule_cells(triangles.len()).to_string(),
            format!("{} × {} × {}", b.cells[0], b.cells[1], b.cells[2]),
            b.entries.to_string(),
            e.entries.to_string(),
            e.empty.to_string(),
            e.longest.to_string(),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

/// Every cell that holds a point of a triangle lists it, whichever fill:
/// sampled points of every triangle of the bunny, and of large random
/// triangles crossing many cells.
#[test]
fn every_cell_a_triangle_touches_lists_it() {
    let mut random = Rng::new(5);
    let mut triangles = bunny();
    let bounds = Aabb::around(triangles.iter().flatten().copied());
    let size = bounds.max - bounds.min;
    for _ in 0..200 {
        let mut corner = || {
            bounds.min
                + DVec3::new(random.unit(), random.unit(), random.unit()) * size
        };
        triangles.push([corner(), corner(), corner()]);
    }
    for fill in [Fill::Boxes, Fill::Exact] {
        let grid = Grid::for_triangles(&triangles, Resolution::Rule, fill);
        let mut missing = 0;
        for (k, t) in triangles.iter().enumerate() {
            for _ in 0..20 {
                let (mut a, mut b) = (random.unit(), random.unit());
                if a + b > 1.0 {
                    (a, b) = (1.0 - a, 1.0 - b);
                }
                let p = t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]);
                let cell = grid.lattice.index(grid.lattice.cell_of(p));
                missing +=
                    usize::from(!grid.cell_objects(cell).contains(&(k as u32)));
            }
        }
        assert_eq!(missing, 0, "{fill:?}");
    }
}

/// The exact test lists a triangle in no cell its plane passes by, and
/// agrees with sampling: a triangle that overlaps a cell by sampled
/// points is never rejected.
#[test]
fn the_exact_test_against_samples() {
    let mut random = Rng::new(8);
    let cell = Aabb::new(DVec3::ZERO, DVec3::ONE);
    let (mut rejected, mut sampled_inside) = (0, 0);
    for _ in 0..2000 {
        let mut corner = || {
            DVec3::new(random.unit(), random.unit(), random.unit()) * 3.0
                - DVec3::ONE
        };
        let t = [corner(), corner(), corner()];
        let overlaps = triangle_overlaps_box(&t, &cell);
        rejected += usize::from(!overlaps);
        for _ in 0..50 {
            let (mut a, mut b) = (random.unit(), random.unit());
            if a + b > 1.0 {
                (a, b) = (1.0 - a, 1.0 - b);
            }
            let p = t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]);
            if cell.contains(p) {
                sampled_inside += 1;
                assert!(overlaps, "{t:?} has {p} inside but was rejected");
            }
        }
    }
    // both answers occur (the test is not always yes or always no)
    assert!(
        rejected > 100 && sampled_inside > 100,
        "{rejected} {sampled_inside}"
    );
}

/// A plane has no finite box: it stays outside the grid, in the list
/// every ray tests, and the grid's box is the other objects'.
#[test]
fn planes_stay_outside() {
    let mut objects =
        sphere_objects(&[(DVec3::ZERO, 1.0), (DVec3::X * 4.0, 1.0)]);
    objects.insert(1, plane_object(DVec3::ZERO, DVec3::Y));
    let grid = Grid::for_objects(&objects, Resolution::Rule);
    assert_eq!(grid.unbounded, vec![1]);
    assert!(!grid.items.contains(&1));
    let b = grid.lattice.bounds;
    assert!(
        b.min.x < -1.0 && b.min.x > -1.001 && b.max.x > 5.0 && b.max.x < 5.001
    );
    // only planes: an empty grid of one cell
    let only = Grid::for_objects(&objects[1..2], Resolution::Rule);
    assert_eq!((only.lattice.cells, only.items.len()), ([1, 1, 1], 0));
}

/// A cell reaches a millionth of its size beyond its box when objects
/// are listed: a box that stops a rounding error short of a cell is
/// listed in it, one that stops a thousandth short is not, one that
/// touches the plane exactly is listed on both sides.
#[test]
fn cells_reach_a_rounding_error_beyond_their_box() {
    let lattice =
        Lattice::new(Aabb::new(DVec3::ZERO, DVec3::splat(4.0)), [4, 4, 4]);
    let ending =
        |x: f64| Aabb::new(DVec3::new(0.2, 0.2, 0.2), DVec3::new(x, 0.8, 0.8));
    let boxes = [ending(1.0 - 1e-9), ending(1.0 - 1e-3), ending(1.0)];
    let grid = Grid::build_on(&boxes, lattice);
    let next = grid.cell_objects(lattice.index([1, 0, 0]));
    assert_eq!(next, &[0, 2], "the cell beyond x = 1 lists {next:?}");
    assert_eq!(grid.cell_objects(0), &[0, 1, 2]);
}

/// A flat scene gets a grid one cell thick; cells stay close to cubes.
#[test]
fn flat_and_long_boxes() {
    let flat = [[
        DVec3::ZERO,
        DVec3::new(4.0, 0.0, 0.0),
        DVec3::new(0.0, 2.0, 0.0),
    ]];
    let grid = Grid::for_triangles(&flat, Resolution::Longest(8), Fill::Exact);
    assert_eq!(grid.lattice.cells, [8, 4, 1]);
    assert!(
        grid.lattice.size.z > 0.0,
        "the flat axis has some thickness"
    );
    let long = Aabb::new(DVec3::ZERO, DVec3::new(100.0, 1.0, 10.0));
    assert_eq!(cells_for(&long, 50), [50, 1, 5]);
    let l = Lattice::new(long, [50, 1, 5]);
    assert_eq!(l.size, DVec3::new(2.0, 1.0, 2.0));
}
