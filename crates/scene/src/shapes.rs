//! Each `[[objects]]` entry's shape key, checked number by number: the
//! chapters get shapes whose sizes are positive and whose corners are in
//! order, and build the geometry themselves.
use std::ops::Range;

use raystep_core::DVec3;
use toml::Spanned;

use crate::error::Context;
use crate::format::{format_number, format_vec};
use crate::raw::{
    Finite, RawBlobby, RawBox, RawCylinder, RawEllipsoid, RawObject, RawPlane,
    RawPolygon, RawSaddle, RawSphere, RawTorus, RawTriangle, Table, Vec3,
};
use crate::scene_meshes::{MeshRequest, placement};
use crate::{Ball, Placement, SceneError, Shape, TorusSolver, TriangleTest};

/// Every shape key, in the order error messages list them.
pub(crate) const KEYS: [&str; 11] = [
    "sphere",
    "plane",
    "polygon",
    "box",
    "cylinder",
    "ellipsoid",
    "triangle",
    "torus",
    "saddle",
    "blobby",
    "mesh",
];

/// An object's shape: checked, or a mesh whose file is read once every
/// field of the scene is checked.
pub(crate) enum ObjectShape {
    /// Any shape but a mesh.
    Ready(Shape),
    /// `mesh = { … }`, its table at `span`.
    Mesh {
        request: MeshRequest,
        placement: Placement,
        span: Range<usize>,
    },
}

/// The one shape of `object`, whose table is at `span`.
pub(crate) fn shape(
    o: RawObject, span: Range<usize>, cx: &Context,
) -> Result<ObjectShape, SceneError> {
    let keys = [
        o.sphere.as_ref().map(Spanned::span),
        o.plane.as_ref().map(Spanned::span),
        o.polygon.as_ref().map(Spanned::span),
        o.aabb.as_ref().map(Spanned::span),
        o.cylinder.as_ref().map(Spanned::span),
        o.ellipsoid.as_ref().map(Spanned::span),
        o.triangle.as_ref().map(Spanned::span),
        o.torus.as_ref().map(Spanned::span),
        o.saddle.as_ref().map(Spanned::span),
        o.blobby.as_ref().map(Spanned::span),
        o.mesh.as_ref().map(Spanned::span),
    ];
    let mut present: Vec<(&str, Range<usize>)> = KEYS
        .iter()
        .zip(keys)
        .filter_map(|(name, span)| Some((*name, span?)))
        .collect();
    present.sort_by_key(|(_, span)| span.start);
    match &present[..] {
        [_] => {}
        [(first, _), (_, second), ..] => {
            return Err(cx.error(
                second.clone(),
                format!(
                    "an object has exactly one shape, this one already has `{first}`"
                ),
            ));
        }
        [] => {
            let (last, others) = KEYS.split_last().expect("eleven keys");
            let list: Vec<String> =
                others.iter().map(|k| format!("`{k}`")).collect();
            return Err(cx.error(
                span,
                format!(
                    "needs a shape: one of {} or `{last}`",
                    list.join(", ")
                ),
            ));
        }
    }
    if let Some(m) = o.mesh {
        let span = m.span();
        let m = inner(m);
        return Ok(ObjectShape::Mesh {
            request: MeshRequest::new(m.obj, m.smooth, cx)?,
            placement: placement(m.scale, m.rotate, m.translate, cx)?,
            span,
        });
    }
    let shape = if let Some(s) = o.sphere {
        sphere(inner(s), cx)
    } else if let Some(p) = o.plane {
        plane(inner(p), cx)
    } else if let Some(p) = o.polygon {
        polygon(inner(p), cx)
    } else if let Some(b) = o.aabb {
        aabb(inner(b), cx)
    } else if let Some(c) = o.cylinder {
        cylinder(inner(c), cx)
    } else if let Some(e) = o.ellipsoid {
        ellipsoid(inner(e), cx)
    } else if let Some(t) = o.triangle {
        triangle(inner(t), cx)
    } else if let Some(t) = o.torus {
        torus(inner(t), cx)
    } else if let Some(s) = o.saddle {
        saddle(inner(s), cx)
    } else if let Some(b) = o.blobby {
        blobby(inner(b), cx)
    } else {
        unreachable!("exactly one shape key is present")
    };
    shape.map(ObjectShape::Ready)
}

/// The number, if it is positive.
pub(crate) fn positive(
    v: &Spanned<Finite>, cx: &Context,
) -> Result<f64, SceneError> {
    let value = v.get_ref().0;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(cx.error(
            v.span(),
            format!("must be positive, got {}", format_number(value)),
        ))
    }
}

/// `[x, y, z]` scaled to a unit vector, if it has a direction. Scaled
/// first, so that a vector like [0, 1e-200, 0] still has one.
fn direction(v: &Spanned<Vec3>, cx: &Context) -> Result<DVec3, SceneError> {
    let n = v.get_ref().0;
    (n / n.abs().max_element()).try_normalize().ok_or_else(|| {
        cx.error(
            v.span(),
            format!("must have a non-zero length, got {}", format_vec(n)),
        )
    })
}

/// One of `names`' values by its name; an error lists the names.
fn named<T: Copy>(
    name: &Spanned<String>, names: &[(&str, T)], cx: &Context,
) -> Result<T, SceneError> {
    names
        .iter()
        .find(|(n, _)| *n == name.get_ref())
        .map(|&(_, value)| value)
        .ok_or_else(|| {
            let known: Vec<String> =
                names.iter().map(|(n, _)| format!("{n:?}")).collect();
            cx.error(
                name.span(),
                format!(
                    "unknown name {:?}, expected one of {}",
                    name.get_ref(),
                    known.join(", ")
                ),
            )
        })
}

fn sphere(s: RawSphere, cx: &Context) -> Result<Shape, SceneError> {
    Ok(Shape::Sphere {
        center: s.center.0,
        radius: positive(&s.radius, cx)?,
    })
}

fn plane(p: RawPlane, cx: &Context) -> Result<Shape, SceneError> {
    Ok(Shape::Plane {
        point: p.point.0,
        normal: direction(&p.normal, cx)?,
    })
}

fn polygon(p: RawPolygon, cx: &Context) -> Result<Shape, SceneError> {
    let count = p.vertices.get_ref().len();
    if count < 3 {
        return Err(cx.error(
            p.vertices.span(),
            format!("a polygon needs at least 3 vertices, got {count}"),
        ));
    }
    Ok(Shape::Polygon {
        vertices: p.vertices.into_inner().into_iter().map(|v| v.0).collect(),
    })
}

fn aabb(b: RawBox, cx: &Context) -> Result<Shape, SceneError> {
    let (min, max) = (b.min.0, b.max.get_ref().0);
    if !min.cmplt(max).all() {
        return Err(cx.error(
            b.max.span(),
            format!(
                "must be greater than min on every axis (a box with no \
                 volume is degenerate), got min = {}, max = {}",
                format_vec(min),
                format_vec(max)
            ),
        ));
    }
    Ok(Shape::Box { min, max })
}

fn cylinder(c: RawCylinder, cx: &Context) -> Result<Shape, SceneError> {
    let (base, top) = (c.base.0, c.top.get_ref().0);
    if (top - base).try_normalize().is_none() {
        return Err(cx.error(
            c.top.span(),
            format!(
                "must differ from base (the axis needs a direction), got \
                 base = {}, top = {}",
                format_vec(base),
                format_vec(top)
            ),
        ));
    }
    Ok(Shape::Cylinder {
        base,
        top,
        radius: positive(&c.radius, cx)?,
    })
}

fn ellipsoid(e: RawEllipsoid, cx: &Context) -> Result<Shape, SceneError> {
    let radii = e.radii.get_ref().0;
    if !radii.cmpgt(DVec3::ZERO).all() {
        return Err(cx.error(
            e.radii.span(),
            format!("must all be positive, got {}", format_vec(radii)),
        ));
    }
    Ok(Shape::Ellipsoid {
        center: e.center.0,
        radii,
    })
}

fn triangle(t: RawTriangle, cx: &Context) -> Result<Shape, SceneError> {
    let vertices: Vec<DVec3> =
        t.vertices.get_ref().iter().map(|v| v.0).collect();
    let Ok(vertices) = <[DVec3; 3]>::try_from(vertices) else {
        return Err(cx.error(
            t.vertices.span(),
            format!(
                "a triangle has exactly 3 vertices, got {}",
                t.vertices.get_ref().len()
            ),
        ));
    };
    let test = match &t.test {
        None => TriangleTest::Watertight,
        Some(name) => named(
            name,
            &[
                ("watertight", TriangleTest::Watertight),
                ("moller-trumbore", TriangleTest::MollerTrumbore),
                ("plane-inside", TriangleTest::PlaneInside),
            ],
            cx,
        )?,
    };
    Ok(Shape::Triangle { vertices, test })
}

fn torus(t: RawTorus, cx: &Context) -> Result<Shape, SceneError> {
    let major = positive(&t.major, cx)?;
    let minor = positive(&t.minor, cx)?;
    if minor >= major {
        return Err(cx.error(
            t.minor.span(),
            format!(
                "must be less than major ({}): only ring tori, got {}; a \
                 spindle or horn torus (minor ≥ major) intersects itself \
                 and is refused",
                format_number(major),
                format_number(minor)
            ),
        ));
    }
    let axis = match &t.axis {
        None => DVec3::Y,
        Some(axis) => direction(axis, cx)?,
    };
    let solver = match &t.solver {
        None => TorusSolver::Bracketed,
        Some(name) => named(
            name,
            &[
                ("bracketed", TorusSolver::Bracketed),
                ("closed-form", TorusSolver::ClosedForm),
            ],
            cx,
        )?,
    };
    Ok(Shape::Torus {
        center: t.center.0,
        axis,
        major,
        minor,
        solver,
    })
}

fn saddle(s: RawSaddle, cx: &Context) -> Result<Shape, SceneError> {
    Ok(Shape::Saddle {
        center: s.center.0,
        size: positive(&s.size, cx)?,
    })
}

fn blobby(b: RawBlobby, cx: &Context) -> Result<Shape, SceneError> {
    if b.balls.get_ref().is_empty() {
        return Err(cx.error(
            b.balls.span(),
            "a blobby object needs at least 1 ball, got 0",
        ));
    }
    let mut balls = Vec::with_capacity(b.balls.get_ref().len());
    for Table(ball) in b.balls.into_inner() {
        balls.push(Ball {
            center: ball.center.0,
            radius: positive(&ball.radius, cx)?,
            strength: match &ball.strength {
                None => 1.0,
                Some(s) => positive(s, cx)?,
            },
        });
    }
    let threshold = positive(&b.threshold, cx)?;
    let total: f64 = balls.iter().map(|b| b.strength).sum();
    if threshold >= total {
        return Err(cx.error(
            b.threshold.span(),
            format!(
                "must be less than the balls' total strength ({}), or \
                 the surface is empty; got {}",
                format_number(total),
                format_number(threshold)
            ),
        ));
    }
    Ok(Shape::Blobby { balls, threshold })
}

/// The struct inside a spanned table.
fn inner<T>(table: Spanned<Table<T>>) -> T {
    table.into_inner().0
}
