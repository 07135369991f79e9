//! Blobby objects: metaballs with Wyvill's soft-object field.
use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

use crate::{BoundingSphere, Primitive, horner, multiply, roots_in};

/// One ball of a [`Blobby`]: its field is `strength` at the centre and
/// falls smoothly to 0 at `radius`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ball {
    /// Its centre.
    pub center: DVec3,
    /// R: where its field reaches 0 (positive).
    pub radius: f64,
    /// Its field at the centre (positive).
    pub strength: f64,
}

// ANCHOR: wyvill
/// Wyvill's soft-object falloff w(ρ) = 1 − (4/9)ρ⁶ + (17/9)ρ⁴ − (22/9)ρ²
/// for ρ < 1, else 0, as a polynomial in q = ρ² (lowest degree first):
/// w is 1 at ρ = 0, ½ at ρ = ½, and 0 with a flat tangent at ρ = 1.
pub const WYVILL: [f64; 4] = [1.0, -22.0 / 9.0, 17.0 / 9.0, -4.0 / 9.0];
// ANCHOR_END: wyvill

/// A blobby object: the points where the balls' summed fields
/// Σ strength·w(|P − C|/R) equal `threshold`; inside, the sum is larger.
#[derive(Clone, Debug, PartialEq)]
pub struct Blobby {
    balls: Vec<Ball>,
    threshold: f64,
}

impl Blobby {
    /// The blob of these balls at this threshold; an error names a bad
    /// parameter (no balls, a radius or strength ≤ 0, a threshold not
    /// between 0 and the sum of the strengths, NaN).
    pub fn new(balls: Vec<Ball>, threshold: f64) -> Result<Blobby, String> {
        if balls.is_empty() {
            return Err("blobby: needs at least one ball".to_string());
        }
        for (i, ball) in balls.iter().enumerate() {
            if !ball.center.is_finite() {
                return Err(format!(
                    "blobby: ball {i}: center {} must be finite",
                    ball.center
                ));
            }
            for (name, value) in
                [("radius", ball.radius), ("strength", ball.strength)]
            {
                if !(value > 0.0 && value.is_finite()) {
                    return Err(format!(
                        "blobby: ball {i}: {name} {value} must be a positive \
                         number"
                    ));
                }
            }
        }
        let total: f64 = balls.iter().map(|b| b.strength).sum();
        if !(threshold > 0.0 && threshold < total) {
            return Err(format!(
                "blobby: threshold {threshold} must be between 0 and the sum \
                 of the strengths, {total} (else there is no surface)"
            ));
        }
        Ok(Blobby { balls, threshold })
    }

    /// Its balls.
    pub fn balls(&self) -> &[Ball] {
        &self.balls
    }

    /// The field value its surface has.
    pub fn threshold(&self) -> f64 {
        self.threshold
    }

    /// The summed field Σ strength·w(|P − C|/R) at `p`.
    pub fn field(&self, p: DVec3) -> f64 {
        self.balls
            .iter()
            .map(|b| {
                let q = (p - b.center).length_squared() / (b.radius * b.radius);
                if q < 1.0 {
                    b.strength * horner(&WYVILL, q)
                } else {
                    0.0
                }
            })
            .sum()
    }

    /// The outward unit normal at `p`: −∇field, normalised.
    pub fn normal_at(&self, p: DVec3) -> DVec3 {
        blobby_normal(&self.balls, p)
    }
}

// ANCHOR: ball_along_ray
/// One ball's field along `ray` as a polynomial in t (degree 6, lowest
/// first), valid while the ray is inside the ball (ρ < 1).
fn ball_along_ray(ball: &Ball, ray: &Ray) -> Vec<f64> {
    // Step 1: q = ρ² = |O + tD − C|²/R², a quadratic in t.
    let oc = ray.origin - ball.center;
    let rr = ball.radius * ball.radius;
    let q = [
        oc.length_squared() / rr,
        2.0 * oc.dot(ray.direction) / rr,
        ray.direction.length_squared() / rr,
    ];
    // Step 2: w(q(t)) by Horner's rule on polynomials,
    // ((w₃·q + w₂)·q + w₁)·q + w₀, then times the strength.
    let mut field = vec![WYVILL[3]];
    for &wk in WYVILL[..3].iter().rev() {
        field = multiply(&field, &q);
        field[0] += wk;
    }
    field.iter().map(|f| ball.strength * f).collect()
}
// ANCHOR_END: ball_along_ray

// ANCHOR: blobby_roots
/// The first t in `interval` where the summed field along `ray` reaches
/// `threshold`.
fn first_crossing(
    balls: &[Ball], threshold: f64, ray: &Ray, interval: Interval,
) -> Option<f64> {
    // Step 1: where the line enters and leaves each ball's sphere (the
    // whole line, not only the interval: the pieces, and so the roots,
    // then do not depend on where the interval starts, and a ray asked
    // again from just past a hit cannot find a new root of the noise).
    let spans: Vec<Interval> = balls
        .iter()
        .map(|b| {
            let sphere = BoundingSphere {
                center: b.center,
                radius: b.radius,
            };
            sphere
                .hit(ray, Interval::UNIVERSE)
                .unwrap_or(Interval::EMPTY)
        })
        .collect();
    // Step 2: cut the ray at every entry and exit; in each piece the same
    // balls are active and the field is one polynomial.
    let mut cuts: Vec<f64> = spans
        .iter()
        .filter(|s| !s.is_empty())
        .flat_map(|s| [s.min, s.max])
        .collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    for piece in cuts.windows(2) {
        let (start, end) = (piece[0], piece[1]);
        if end < interval.min {
            continue; // wholly before the interval
        }
        if start > interval.max {
            break; // and every later piece too
        }
        let middle = 0.5 * (start + end);
        // Step 3: move the origin to the piece's start and sum the active
        // balls' polynomials, minus the threshold.
        let moved = Ray::new(ray.at(start), ray.direction);
        let mut sum = vec![0.0; 7];
        sum[0] = -threshold;
        for (ball, span) in balls.iter().zip(&spans) {
            if span.contains(middle) {
                for (s, f) in sum.iter_mut().zip(ball_along_ray(ball, &moved)) {
                    *s += f;
                }
            }
        }
        // Step 4: its first root in the interval is the hit.
        let first = roots_in(&sum, 0.0, end - start)
            .into_iter()
            .map(|s| start + s)
            .find(|&t| interval.contains(t));
        if first.is_some() {
            return first;
        }
    }
    None
}
// ANCHOR_END: blobby_roots

// ANCHOR: blobby_normal
/// −∇field at `p`, normalised. With ρ² = |P − C|²/R², the gradient of
/// one ball is strength·(w′(ρ)/ρ)·(P − C)/R², and
/// w′(ρ)/ρ = −44/9 + (68/9)ρ² − (24/9)ρ⁴ has no division by ρ.
fn blobby_normal(balls: &[Ball], p: DVec3) -> DVec3 {
    let mut gradient = DVec3::ZERO;
    for ball in balls {
        let (v, rr) = (p - ball.center, ball.radius * ball.radius);
        let q = v.length_squared() / rr;
        if q < 1.0 {
            let slope = -44.0 / 9.0 + 68.0 / 9.0 * q - 24.0 / 9.0 * q * q;
            gradient += ball.strength * slope / rr * v;
        }
    }
    // Where the balls' pulls cancel (midway between two equal balls) the
    // gradient vanishes: then away from the nearest centre, or up.
    (-gradient).try_normalize().unwrap_or_else(|| {
        let nearest = balls
            .iter()
            .map(|b| p - b.center)
            .min_by(|a, b| a.length_squared().total_cmp(&b.length_squared()));
        nearest.and_then(DVec3::try_normalize).unwrap_or(DVec3::Y)
    })
}
// ANCHOR_END: blobby_normal

/// A blob as an object of a scene.
impl Shape for Blobby {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        let t = first_crossing(&self.balls, self.threshold, ray, interval)?;
        let point = ray.at(t);
        let normal = blobby_normal(&self.balls, point);
        Some(Hit { t, point, normal })
    }

    /// The union of the balls' boxes (no field outside them).
    fn bounds(&self) -> Aabb {
        self.balls.iter().fold(Aabb::EMPTY, |b, ball| {
            let r = DVec3::splat(ball.radius);
            b.union(Aabb::new(ball.center - r, ball.center + r))
        })
    }
}

impl Primitive for Blobby {
    fn name(&self) -> &'static str {
        "blobby"
    }

    /// Around the centre of its box, out to the farthest ball's sphere.
    fn bounding_sphere(&self) -> BoundingSphere {
        let b = self.bounds();
        let center = 0.5 * (b.min + b.max);
        let radius = self
            .balls
            .iter()
            .map(|ball| (ball.center - center).length() + ball.radius)
            .fold(0.0, f64::max);
        BoundingSphere { center, radius }
    }
}
