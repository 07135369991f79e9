//! Exercise 1: the DDA's setup. The first cell, and per axis the step,
//! the t of the next plane between cells and the t between two planes,
//! for hand-worked rays through a grid of unit cells.
use ch09::{Aabb, DVec3, Dda, Interval, Lattice, Ray, dda_setup};
use raystep_check::{Table, num};

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

#[test]
fn setup_table() {
    let mut table = Table::new(&[
        "ray", "cell", "step", "t_max", "t_delta", "t_enter", "t_exit",
    ]);
    for (name, ray, interval) in cases() {
        match dda_setup(&lattice(), &ray, interval) {
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
    insta::assert_snapshot!(table.to_string());
}

/// The diagonal ray worked by hand: from (0.5, 0.5) along (1, 2) it meets
/// y = 1 at t = 0.25 and x = 1 at t = 0.5; a cell is 1 wide in x (t 1)
/// and 1 high in y (t 0.5); it never crosses a z plane.
#[test]
fn the_diagonal_by_hand() {
    let (_, ray, interval) = cases()[1];
    let d = dda_setup(&lattice(), &ray, interval).expect("inside the box");
    assert_eq!(d.cell, [0, 0, 0]);
    assert_eq!(d.step, [1, 1, 0]);
    assert_eq!(d.t_max, DVec3::new(0.5, 0.25, f64::INFINITY));
    assert_eq!(d.t_delta, DVec3::new(1.0, 0.5, f64::INFINITY));
    assert_eq!(d.t_enter, 0.0);
}

/// Going toward −x, the next plane is the cell's own lower one; a ray
/// starting on a plane belongs to the cell above (the tie rule), so going
/// down it leaves that cell at once (t_max = 0).
#[test]
fn going_down_the_next_plane_is_the_cells_own() {
    let (_, ray, interval) = cases()[2];
    let d = dda_setup(&lattice(), &ray, interval).unwrap();
    assert_eq!((d.cell, d.step), ([3, 2, 1], [-1, -1, -1]));
    assert_eq!(d.t_max, DVec3::splat(0.5));
    assert_eq!(d.t_delta, DVec3::ONE);
    let (_, ray, interval) = cases()[4];
    let d = dda_setup(&lattice(), &ray, interval).unwrap();
    assert_eq!(d.cell, [2, 1, 1]);
    assert!(
        d.t_max.to_array().iter().all(|&t| t == 0.0),
        "{:?}",
        d.t_max
    );
}

/// A zero component, +0.0 or −0.0, never crosses a plane: step 0 and
/// +∞, not −∞ and not NaN (0/0).
#[test]
fn a_parallel_axis_never_steps() {
    for y in [0.0, -0.0] {
        let r = ray([0.5, 1.0, 0.5], [1.0, y, 0.0]);
        let d = dda_setup(&lattice(), &r, Interval::FORWARD).unwrap();
        assert_eq!(d.step[1], 0);
        assert_eq!(d.t_max.y, f64::INFINITY);
        assert_eq!(d.t_delta.y, f64::INFINITY);
        assert_eq!(d.cell[1], 1, "on the plane y = 1: the cell above");
    }
}

/// The box clips the ray, the interval clips the box: a ray that misses
/// the box, or meets it only outside the interval, has no setup.
#[test]
fn the_box_and_the_interval_clip_the_walk() {
    let r = ray([-1.0, 0.5, 0.5], [1.0, 0.0, 0.0]);
    let l = lattice();
    assert!(dda_setup(&l, &r, Interval::new(0.0, 0.5)).is_none());
    let d = dda_setup(&l, &r, Interval::new(2.0, 3.0)).unwrap();
    assert_eq!((d.cell, d.t_enter, d.t_exit), ([1, 0, 0], 2.0, 3.0));
    assert_eq!(d.t_max.x, 3.0);
    let (_, miss, interval) = cases()[6];
    assert!(dda_setup(&l, &miss, interval).is_none());
}
