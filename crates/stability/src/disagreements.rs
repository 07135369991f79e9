//! An accelerator against brute force: the three answers a tracer asks
//! of it for a ray, and how many rays it answers otherwise.
use ch03::BruteForce;
use raystep_core::{Interval, Ray};
use raystep_world::{Accelerator, Object};

/// Brute force's three answers for a ray: the closest hit's t, and any
/// hit over t ≥ 0 and over 0 ≤ t ≤ 1.
pub type Answers = (Option<f64>, bool, bool);

/// What `accelerator` answers for `ray` (brute force: [`BruteForce`]).
pub fn answers(
    accelerator: &dyn Accelerator, objects: &[Object], ray: &Ray,
) -> Answers {
    let short = Interval::new(0.0, 1.0);
    (
        accelerator
            .closest_hit(objects, ray, Interval::FORWARD)
            .map(|(_, hit)| hit.t),
        accelerator.any_hit(objects, ray, Interval::FORWARD),
        accelerator.any_hit(objects, ray, short),
    )
}

/// For each of `accelerators`, how many of `rays` it answers unlike
/// brute force, as `agree(ours, brute force's)` judges two answers.
pub fn disagreements_by(
    accelerators: &[&dyn Accelerator], objects: &[Object], rays: &[Ray],
    agree: impl Fn(&Answers, &Answers) -> bool,
) -> Vec<usize> {
    let mut wrong = vec![0; accelerators.len()];
    for ray in rays {
        let truth = answers(&BruteForce, objects, ray);
        for (count, accelerator) in wrong.iter_mut().zip(accelerators) {
            let ours = answers(*accelerator, objects, ray);
            *count += usize::from(!agree(&ours, &truth));
        }
    }
    wrong
}

/// For each of `accelerators`, how many of `rays` it answers differently
/// from brute force (a closest hit at another t, a hit against a miss,
/// another any-hit answer). Two objects hit at the very same t are a
/// tie, not a disagreement.
pub fn kd_disagreements(
    accelerators: &[&dyn Accelerator], objects: &[Object], rays: &[Ray],
) -> Vec<usize> {
    disagreements_by(accelerators, objects, rays, |a, b| a == b)
}

/// How many of `rays` `accelerator` answers differently from brute force
/// ([`kd_disagreements`] of one).
pub fn disagreements(
    accelerator: &dyn Accelerator, objects: &[Object], rays: &[Ray],
) -> usize {
    kd_disagreements(&[accelerator], objects, rays)[0]
}
