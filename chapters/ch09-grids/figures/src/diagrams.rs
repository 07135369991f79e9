//! Chapter 9's lecture figures, each drawn from the chapter's own code:
//! a grid's cell lists and one ray's walk, the DDA's setup, the walk
//! beside chapter 7's rasterizer, and the teapot in a stadium.
use std::sync::Arc;

use ch08::SplitMix64;
use ch09::{
    Aabb, DVec3, Grid, Interval, Lattice, Object, Ray, Resolution, dda_setup,
    walk,
};
use raystep_figure::{Anchor, DVec2, Figure, Page, Stroke, palette};
use raystep_render::{Progress, RenderOptions};

/// Every lecture figure of the chapter.
pub fn all() -> Vec<Figure> {
    vec![
        grid_walk(),
        dda_setup_figure(),
        raster_analogy(),
        stadium_heat(),
    ]
}

/// A point of the plane z = 0 as a figure point.
fn flat(p: DVec3) -> DVec2 {
    DVec2::new(p.x, p.y)
}

/// A lattice of unit cells `w × h` in the plane z = 0 (one cell deep).
fn flat_lattice(w: usize, h: usize) -> Lattice {
    Lattice::new(
        Aabb::new(
            DVec3::new(0.0, 0.0, -0.5),
            DVec3::new(w as f64, h as f64, 0.5),
        ),
        [w, h, 1],
    )
}

/// The lattice's lines.
fn draw_lines(page: &mut Page, lattice: &Lattice, stroke: &Stroke) {
    let [w, h, _] = lattice.cells;
    for i in 0..=w {
        let x = lattice.plane(0, i);
        page.segment(
            DVec2::new(x, lattice.bounds.min.y),
            DVec2::new(x, lattice.bounds.max.y),
            stroke,
        );
    }
    for j in 0..=h {
        let y = lattice.plane(1, j);
        page.segment(
            DVec2::new(lattice.bounds.min.x, y),
            DVec2::new(lattice.bounds.max.x, y),
            stroke,
        );
    }
}

/// A cell's square, filled.
fn fill_cell(
    page: &mut Page, lattice: &Lattice, cell: [usize; 3],
    fill: raystep_figure::Fill,
) {
    let b = lattice.cell_box(cell);
    page.polygon_alpha(
        &[
            DVec2::new(b.min.x, b.min.y),
            DVec2::new(b.max.x, b.min.y),
            DVec2::new(b.max.x, b.max.y),
            DVec2::new(b.min.x, b.max.y),
        ],
        Some(fill),
        None,
    );
}

/// The ray of the walk figure.
fn walk_ray() -> Ray {
    Ray::new(DVec3::new(0.3, 0.6, 0.0), DVec3::new(1.0, 0.4925, 0.0))
}

/// The circles of the walk figure: spheres in the plane z = 0, small
/// ones spread at random (none on the ray's way) and one large one
/// across nine cells, which the ray meets first in a cell where its hit
/// does not lie.
fn walk_spheres() -> Vec<(DVec3, f64)> {
    let ray = walk_ray();
    let direction = ray.direction.normalize();
    let off_ray = |c: DVec3| {
        let along = (c - ray.origin).dot(direction).max(0.0);
        (c - ray.origin - along * direction).length()
    };
    let mut random = SplitMix64::new(21);
    let mut spheres = vec![(DVec3::new(8.2, 4.7, 0.0), 0.9)];
    while spheres.len() < 24 {
        let c = DVec3::new(
            0.4 + 11.2 * random.next_f64(),
            0.4 + 6.2 * random.next_f64(),
            0.0,
        );
        let r = 0.22 + 0.12 * random.next_f64();
        let apart = spheres.iter().all(|(o, s)| o.distance(c) > s + r + 0.15);
        if apart && off_ray(c) > r + 0.08 {
            spheres.push((c, r));
        }
    }
    spheres
}

/// The grid of the lecture: every cell lists the circles whose boxes
/// overlap it; one ray walks the cells in order and stops in the first
/// cell that holds a hit.
fn grid_walk() -> Figure {
    let spheres = walk_spheres();
    let objects: Vec<Object> = spheres
        .iter()
        .map(|&(center, radius)| Object {
            shape: ch08::shape(&raystep_scene::Shape::Sphere {
                center,
                radius,
            })
            .expect("a sphere"),
            material: 0,
        })
        .collect();
    // the figure's lattice: unit cells over [0, 12] × [0, 7]
    let lattice = flat_lattice(12, 7);
    let boxes: Vec<Aabb> = objects.iter().map(|o| o.shape.bounds()).collect();
    let grid = Grid::build_on(&boxes, lattice);
    let ray = walk_ray();
    let mut visits = Vec::new();
    let mut tested = Vec::new();
    let hit = grid.closest_hit_observed(
        &objects,
        &ray,
        Interval::FORWARD,
        &mut |visit, object| match object {
            None => visits.push(visit),
            Some(k) => tested.push((visits.len() - 1, k)),
        },
    );
    let mut page = Page::new(900.0, 600.0)
        .view(DVec2::new(-0.3, -1.1), DVec2::new(12.3, 7.3));
    for (k, visit) in visits.iter().enumerate() {
        let last = k + 1 == visits.len();
        let fill = if last {
            palette::ORANGE.with_alpha(0.35)
        } else {
            palette::SKY_BLUE.with_alpha(0.3)
        };
        fill_cell(&mut page, &lattice, visit.cell, fill);
        let b = lattice.cell_box(visit.cell);
        page.label_sized(
            DVec2::new(b.min.x + 0.06, b.min.y + 0.05),
            &(k + 1).to_string(),
            Anchor::NE,
            13.0,
            palette::BLUE,
        );
    }
    draw_lines(&mut page, &lattice, &Stroke::new(palette::GREY).width(1.0));
    // each cell's list length, top right
    for y in 0..7 {
        for x in 0..12 {
            let n = grid.cell_objects(lattice.index([x, y, 0])).len();
            if n > 0 {
                page.label_sized(
                    DVec2::new(x as f64 + 0.95, y as f64 + 0.97),
                    &n.to_string(),
                    Anchor::SW,
                    12.0,
                    palette::NOTE,
                );
            }
        }
    }
    let was_tested = |i: usize| tested.iter().any(|&(_, k)| k as usize == i);
    for (i, &(c, r)) in spheres.iter().enumerate() {
        let hit_here = hit.is_some_and(|(k, _)| k == i);
        let (fill, stroke) = if hit_here {
            (
                palette::VERMILION.with_alpha(0.55),
                Stroke::new(palette::VERMILION).width(2.0),
            )
        } else if was_tested(i) {
            (
                palette::ORANGE.with_alpha(0.45),
                Stroke::new(palette::ORANGE).width(1.5),
            )
        } else {
            (
                palette::GREY.with_alpha(0.35),
                Stroke::new(palette::GREY).width(1.0),
            )
        };
        page.circle_alpha(flat(c), r, Some(fill), Some(&stroke));
    }
    let end = hit.map_or(14.0, |(_, h)| h.t);
    let ray_stroke = Stroke::new(palette::BLUE).width(2.5);
    page.arrow(flat(ray.origin), flat(ray.at(end)), &ray_stroke);
    if let Some((_, h)) = hit {
        page.cross(flat(h.point));
    }
    page.point(flat(ray.origin), palette::BLUE);
    // where the big circle was first tested: its hit lies further on
    let first_test = tested
        .iter()
        .find(|&&(_, k)| hit.is_some_and(|(i, _)| i == k as usize))
        .map(|&(cell, _)| visits[cell]);
    if let (Some(v), Some((_, h))) = (first_test, hit)
        && v.t_out < h.t
    {
        let b = lattice.cell_box(v.cell);
        let number = visits.iter().position(|w| w.cell == v.cell).unwrap_or(0);
        page.label_sized(
            DVec2::new(b.min.x + 0.05, b.min.y - 0.3),
            &format!("cell {} finds the hit beyond it: walk on", number + 1),
            Anchor::E,
            14.0,
            palette::VERMILION,
        );
    }
    page.text_page(
        DVec2::new(14.0, 556.0),
        &format!(
            "blue: the {} cells the ray walked, in order · orange: the cell that holds the hit, where the walk stops",
            visits.len()
        ),
        Anchor::E,
        15.0,
    );
    page.text_page(
        DVec2::new(14.0, 582.0),
        "small grey numbers: how many objects the cell lists · orange circles: tested and missed · vermilion: the hit",
        Anchor::E,
        15.0,
    );
    Figure::new(
        "grid-walk",
        &format!(
            "A grid of 12 × 7 cells over 24 circles (spheres cut by z = 0), built and walked by the chapter's code: each cell lists the circles whose bounding boxes overlap it (grey numbers; the big circle is in {} lists). The ray walks the cells in order and tests the objects listed there ({} tests in {} cells, none twice: the mailbox). It meets the big circle first in a cell where the hit does not lie; the hit is kept, and the walk goes on to the cell that holds it (a closer hit could still wait in between), then stops: the cells beyond are never looked at.",
            (0..lattice.count())
                .filter(|&c| grid.cell_objects(c).contains(&0))
                .count(),
            tested.len(),
            visits.len()
        ),
        page,
    )
}

/// The DDA's setup on a few unit cells: where the ray crosses the next
/// vertical plane (t_max,x) and the next horizontal one (t_max,y), and
/// the equal steps between crossings (t_delta).
fn dda_setup_figure() -> Figure {
    let lattice = flat_lattice(5, 3);
    let ray = Ray::new(DVec3::new(0.35, 0.45, 0.0), DVec3::new(1.0, 0.45, 0.0));
    let d = dda_setup(&lattice, &ray, Interval::FORWARD).expect("inside");
    let mut page = Page::new(900.0, 530.0)
        .view(DVec2::new(-0.3, -1.3), DVec2::new(5.3, 3.3));
    fill_cell(
        &mut page,
        &lattice,
        d.cell,
        palette::SKY_BLUE.with_alpha(0.3),
    );
    draw_lines(&mut page, &lattice, &Stroke::new(palette::GREY).width(1.0));
    let ray_stroke = Stroke::new(palette::BLUE).width(2.5);
    page.arrow(flat(ray.origin), flat(ray.at(d.t_exit)), &ray_stroke);
    page.point(flat(ray.origin), palette::BLUE);
    page.label(flat(ray.origin), "origin", Anchor::SW);
    // the crossings with x planes (vermilion) and y planes (green)
    for (axis, colour, anchor, nudge) in [
        (0, palette::VERMILION, Anchor::SE, DVec2::ZERO),
        (1, palette::GREEN, Anchor::NW, DVec2::new(-0.05, 0.1)),
    ] {
        let name = ["x", "y"][axis];
        let mut t = d.t_max[axis];
        let mut first = true;
        while t < d.t_exit {
            let p = flat(ray.at(t));
            page.circle(p, 0.06, Some(colour), None);
            let text = if first {
                format!("t_{{max,{name}}}")
            } else {
                format!("+ t_{{delta,{name}}}")
            };
            page.label_sized(p + nudge, &text, anchor, 16.0, colour);
            t += d.t_delta[axis];
            first = false;
        }
    }
    let lines = [
        format!(
            "first cell ({}, {}) · t_{{max}} = ({:.2}, {:.2}): where the next x and y planes are",
            d.cell[0], d.cell[1], d.t_max.x, d.t_max.y
        ),
        format!(
            "t_{{delta}} = ({:.2}, {:.2}): one cell's width and height, in t",
            d.t_delta.x, d.t_delta.y
        ),
        "each step: the smaller t_{max} says which plane comes first; step across it and add that axis's t_{delta}".to_string(),
    ];
    for (k, line) in lines.iter().enumerate() {
        page.text_page(
            DVec2::new(14.0, 440.0 + 26.0 * k as f64),
            line,
            Anchor::E,
            16.0,
        );
    }
    Figure::new(
        "dda-setup",
        "The 3D DDA's setup (exercise 1), drawn in the plane: from the origin the ray meets the next vertical plane at t_max,x (vermilion) and the next horizontal plane at t_max,y (green). Each further crossing of an axis's planes comes t_delta of that axis later, so the walk needs one comparison and one addition per cell (exercise 2): the vermilion and green dots, taken in order of t, are exactly the walls between the cells it visits.",
        page,
    )
}

/// The walk beside chapter 7's rasterizer, over the same 12 × 8 grid.
fn raster_analogy() -> Figure {
    let (w, h) = (12usize, 8usize);
    let lattice = flat_lattice(w, h);
    let (a, b) = (DVec2::new(0.5, 0.8), DVec2::new(11.6, 6.9));
    // a triangle whose upper edge is the ray's segment
    let triangle = [a, DVec2::new(11.3, 0.9), b];
    let ray = Ray::new(
        DVec3::new(a.x, a.y, 0.0),
        DVec3::new(b.x - a.x, b.y - a.y, 0.0),
    );
    let gap = 1.2;
    let mut page = Page::new(900.0, 400.0).view(
        DVec2::new(-0.2, -1.6),
        DVec2::new(2.0 * w as f64 + gap + 0.2, h as f64 + 0.3),
    );
    // left: the rasterizer tests every pixel centre in the triangle's box
    let lo = triangle.iter().fold(DVec2::INFINITY, |m, p| m.min(*p));
    let hi = triangle.iter().fold(DVec2::NEG_INFINITY, |m, p| m.max(*p));
    let (mut covered, mut tested) = (0, 0);
    for y in 0..h {
        for x in 0..w {
            let centre = DVec2::new(x as f64 + 0.5, y as f64 + 0.5);
            if centre.cmplt(lo).any() || centre.cmpgt(hi).any() {
                continue;
            }
            tested += 1;
            let fill = if ch07::covers(&triangle, centre) {
                covered += 1;
                palette::ORANGE.with_alpha(0.55)
            } else {
                palette::LIGHT_GREY.with_alpha(0.6)
            };
            fill_cell(&mut page, &lattice, [x, y, 0], fill);
            page.circle(centre, 0.05, Some(palette::NOTE), None);
        }
    }
    draw_lines(&mut page, &lattice, &Stroke::new(palette::GREY).width(1.0));
    page.polygon(
        &triangle,
        None,
        Some(&Stroke::new(palette::VERMILION).width(2.0)),
    );
    // its upper edge is the ray the walk on the right follows
    page.segment(a, b, &Stroke::new(palette::BLUE).width(2.5));
    // right: the walk visits every cell the ray passes through
    let shift = DVec2::new(w as f64 + gap, 0.0);
    let mut visited = 0;
    walk(&lattice, &ray, Interval::new(0.0, 1.0), |v| {
        visited += 1;
        let b = lattice.cell_box(v.cell);
        page.polygon_alpha(
            &[
                shift + DVec2::new(b.min.x, b.min.y),
                shift + DVec2::new(b.max.x, b.min.y),
                shift + DVec2::new(b.max.x, b.max.y),
                shift + DVec2::new(b.min.x, b.max.y),
            ],
            Some(palette::SKY_BLUE.with_alpha(0.45)),
            None,
        );
        std::ops::ControlFlow::Continue(())
    });
    let grey = Stroke::new(palette::GREY).width(1.0);
    for i in 0..=w {
        page.segment(
            shift + DVec2::new(i as f64, 0.0),
            shift + DVec2::new(i as f64, h as f64),
            &grey,
        );
    }
    for j in 0..=h {
        page.segment(
            shift + DVec2::new(0.0, j as f64),
            shift + DVec2::new(w as f64, j as f64),
            &grey,
        );
    }
    page.arrow(shift + a, shift + b, &Stroke::new(palette::BLUE).width(2.5));
    page.label(
        DVec2::new(w as f64 / 2.0, -0.8),
        &format!(
            "rasterizer: {tested} pixel centres tested, {covered} covered"
        ),
        Anchor::Center,
    );
    page.label(
        shift + DVec2::new(w as f64 / 2.0, -0.8),
        &format!("grid walk: {visited} cells, each one entered"),
        Anchor::Center,
    );
    Figure::new(
        "dda-raster",
        "The grid walk beside chapter 7's rasterizer, on the same 12 × 8 grid. Left: the rasterizer tests the centre of every pixel in a triangle's box (grey) and draws those it covers (orange, chapter 7's `covers`); from one pixel to the next each edge function grows by a constant. Right: the DDA walks along the triangle's upper edge (blue) as a ray, from cell to cell, adding a constant t_delta at each step; it visits every cell the ray passes through, not only those whose centre lies on one side. Both break ties the same way: a point on the line between two cells belongs to the cell above or to the right, as chapter 2's rule gives a pixel centre on a shared edge to exactly one triangle.",
        page,
    )
}

/// The teapot in a stadium (`scenes/teapot-in-stadium.toml`, the bunny
/// from ../shared): the render, and from the side the grid's cells
/// through the bunny coloured by how many objects each lists.
fn stadium_heat() -> Figure {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../scenes/teapot-in-stadium.toml");
    let scene = raystep_scene::load(&path).expect(
        "the chapter's scene loads (with ../shared beside the workspace)",
    );
    let grid_of = |objects: &[Object]| -> Arc<dyn ch09::Accelerator> {
        Arc::new(Grid::for_objects(objects, Resolution::Rule))
    };
    let world = ch08::world(&scene, "teapot-in-stadium.toml")
        .expect("the scene builds")
        .accelerated(grid_of);
    let options = RenderOptions {
        threads: None,
        progress: Progress::Never,
    };
    let (image, _) = ch06::render(
        &world,
        &ch06::DEFAULT_STOP,
        ch06::Fresnel::Exact,
        &options,
    )
    .expect("the scene renders");
    let grid = Grid::for_objects(&world.objects, Resolution::Rule);
    let lattice = grid.lattice;
    let [nx, ny, nz] = lattice.cells;
    // the slice of cells through the teapot (at z = 0, through the
    // middle of the bunny), seen from the side
    let z = lattice.cell_of(DVec3::new(0.0, 0.5, 0.0))[2];
    let count =
        |x: usize, y: usize| grid.cell_objects(lattice.index([x, y, z])).len();
    let max = (0..nx)
        .flat_map(|x| (0..ny).map(move |y| (x, y)))
        .map(|(x, y)| count(x, y))
        .max()
        .unwrap_or(1)
        .max(2);
    // cells that list triangles of the teapot (the objects after the
    // five boxes): in the whole grid, and in the slice drawn
    let teapot = |c: usize| grid.cell_objects(c).iter().any(|&k| k >= 5);
    let teapot_cells = (0..lattice.count()).filter(|&c| teapot(c)).count();
    let slice_cells = (0..nx)
        .flat_map(|x| (0..ny).map(move |y| (x, y)))
        .filter(|&(x, y)| teapot(lattice.index([x, y, z])))
        .count();
    let (iw, ih) = (f64::from(image.width()), f64::from(image.height()));
    let mut page = Page::new(900.0, ih + 60.0);
    let at = |page: &Page, x: f64, y: f64| page.to_world(DVec2::new(x, y));
    page.image(
        at(&page, 10.0, 40.0 + ih),
        at(&page, 10.0 + iw, 40.0),
        image.width(),
        image.height(),
        &image.to_srgb8(),
    );
    // the slice, in page px: x → right, y → up
    let (left, bottom) = (iw + 30.0, 40.0 + ih - 30.0);
    let cell = (900.0 - left - 15.0) / nx as f64;
    for y in 0..ny {
        for x in 0..nx {
            let n = count(x, y);
            let colour = if n == 0 {
                palette::WHITE
            } else {
                let level = (n as f64).ln() / (max as f64).ln();
                palette::SKY_BLUE.mix(palette::VERMILION, level)
            };
            let (x0, y0) = (left + x as f64 * cell, bottom - y as f64 * cell);
            page.polygon(
                &[
                    at(&page, x0, y0),
                    at(&page, x0 + cell, y0),
                    at(&page, x0 + cell, y0 - cell),
                    at(&page, x0, y0 - cell),
                ],
                Some(colour),
                Some(&Stroke::new(palette::LIGHT_GREY).width(0.5)),
            );
        }
    }
    // the full cells' counts, above them, with an arrow down
    let full: Vec<(usize, usize)> = (0..nx)
        .filter_map(|x| (count(x, 0) > 9).then_some((x, count(x, 0))))
        .collect();
    if let (Some(&(first, _)), Some(&(last, _))) = (full.first(), full.last()) {
        let middle = left + (first + last + 1) as f64 / 2.0 * cell;
        let counts: Vec<String> =
            full.iter().map(|(_, n)| n.to_string()).collect();
        page.arrow(
            at(&page, middle, bottom - 3.0 * cell),
            at(&page, middle, bottom - 1.1 * cell),
            &Stroke::new(palette::BLACK).width(1.5),
        );
        page.label_sized(
            at(&page, middle, bottom - 3.0 * cell),
            &format!("{} objects", counts.join(" + ")),
            Anchor::N,
            14.0,
            palette::BLACK,
        );
    }
    page.text_page(
        DVec2::new(10.0, 24.0),
        "the render, traced through the grid",
        Anchor::E,
        15.0,
    );
    page.text_page(
        DVec2::new(left, bottom - ny as f64 * cell - 40.0),
        &format!("the cells through the teapot, from the side (a slice of {nx} × {ny} × {nz})"),
        Anchor::E,
        15.0,
    );
    page.text_page(
        DVec2::new(left, bottom + 24.0),
        &format!("white: empty · blue: 1 object (the floor, a wall) · vermilion: {max} objects"),
        Anchor::E,
        14.0,
    );
    Figure::new(
        "stadium-heat",
        &format!(
            "The teapot in a stadium (scenes/teapot-in-stadium.toml): the bunny's {} triangles at size 1, inside a box 200 wide with walls 50 high. The rule gives {nx} × {ny} × {nz} cells of {:.1} units for its {} objects, so the bunny's triangles crowd into {teapot_cells} cells, {slice_cells} of them in the slice drawn (up to {max} objects each there; colours on a log scale), while nearly every other cell is empty: a ray through the teapot tests hundreds of triangles, and a ray that misses it walks dozens of empty cells.",
            world.objects.len() - 5,
            lattice.size.x,
            world.objects.len()
        ),
        page,
    )
}
