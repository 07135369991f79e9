//! The kd-tree against brute force, on the rays and scenes where a tree
//! can go wrong (the stability catalogue, a few rays of each kind here;
//! `raystep measure` asks over a million), and on the bunny.
mod common;

use ch10::{
    Accelerator, Clip, KdBuilder, KdCosts, KdTree, kd_disagreements, kd_rays,
    kd_scenes,
};

/// Rays of each kind per scene and tree.
const PER_CASE: usize = 40;

#[test]
fn every_tree_agrees_with_brute_force_on_the_catalogue() {
    let bunny = common::bunny();
    let mut table = String::from(
        "scene | rays | SAH | SAH, no mailbox | median | SAH, pbrt's costs\n",
    );
    let mut total = 0;
    for scene in kd_scenes(&bunny) {
        let sah = KdTree::for_objects(
            &scene.objects,
            KdBuilder::SahEvents,
            KdCosts::CHOSEN,
        );
        let mut plain = sah.clone();
        plain.mailboxing = false;
        let median = KdTree::for_objects(
            &scene.objects,
            KdBuilder::Median,
            KdCosts::CHOSEN,
        );
        // the same four trees as `raystep measure`'s catalogue
        let pbrt = KdTree::for_objects(
            &scene.objects,
            KdBuilder::SahEvents,
            KdCosts::PBRT_V3,
        );
        let trees: [&dyn Accelerator; 4] = [&sah, &plain, &median, &pbrt];
        let mut wrong = vec![0; trees.len()];
        let mut rays = 0;
        for (seed, tree) in [&sah, &median, &pbrt].into_iter().enumerate() {
            for case in kd_rays(tree, PER_CASE, seed as u64) {
                rays += case.rays.len();
                for (w, d) in wrong.iter_mut().zip(kd_disagreements(
                    &trees,
                    &scene.objects,
                    &case.rays,
                )) {
                    *w += d;
                }
            }
        }
        total += wrong.iter().sum::<usize>();
        table += &format!(
            "{} | {rays} | {}\n",
            scene.name,
            wrong
                .iter()
                .map(|w| w.to_string())
                .collect::<Vec<_>>()
                .join(" | ")
        );
    }
    println!("{table}");
    assert_eq!(total, 0, "disagreements with brute force:\n{table}");
    let _ = Clip::Boxes;
}
