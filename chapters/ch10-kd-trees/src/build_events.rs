//! The O(N log N) SAH build (Wald and Havran 2006): the events are
//! sorted once, at the root. A node's plane splits each axis's sorted
//! list into its children's lists *in order*; only the objects the plane
//! cuts get new events (their boxes cut to each child), few enough to
//! sort, then merged in. Each level costs O(N): O(N log N) in all.
use raystep_core::Aabb;

use crate::builder_io::{Input, Output};
use crate::events::{
    EventKind, Plane, Side, children, push_events, sweep, worth_splitting,
};
use crate::{Event, event_order};

/// Builds the tree over `objects` in box `node`.
pub(crate) fn build(
    input: &Input, objects: &[u32], node: Aabb, out: &mut Output,
) {
    // Step 1: every object's events, sorted once.
    let events = [0, 1, 2].map(|axis| {
        let mut events = Vec::with_capacity(2 * objects.len());
        for &i in objects {
            push_events(&mut events, i, &input.bounds_in(i, &node), axis);
        }
        events.sort_unstable_by(event_order);
        events
    });
    let mut sides = vec![Side::Both; input.boxes.len()];
    subtree(input, events, objects.len(), node, 0, &mut sides, out);
}

/// The objects of a node: each has one start or flat event per axis.
fn objects_of(events: &[Event]) -> impl Iterator<Item = u32> + '_ {
    events
        .iter()
        .filter(|e| e.kind != EventKind::End)
        .map(|e| e.object)
}

fn subtree(
    input: &Input, events: [Vec<Event>; 3], count: usize, node: Aabb,
    depth: usize, sides: &mut [Side], out: &mut Output,
) {
    // Step 2: the cheapest plane: one sweep per axis, no sorting.
    let mut best = None;
    if count > 0 && depth < input.max_depth {
        for (axis, events) in events.iter().enumerate() {
            sweep(events, axis, count, &node, &input.costs, &mut best);
        }
    }
    let Some(plane) = best.filter(|p| worth_splitting(p, count, &input.costs))
    else {
        out.leaf(objects_of(&events[0]));
        return;
    };
    // Step 3: each object's side, read off the plane's own axis.
    let cut = classify(&events[plane.axis], &plane, sides);
    // Step 4: the cut objects' boxes in each child, as new sorted events.
    let (below_box, above_box) = children(&node, plane.axis, plane.position);
    let fresh = |child: &Aabb| {
        [0, 1, 2].map(|axis| {
            let mut new = Vec::with_capacity(2 * cut.len());
            for &i in &cut {
                push_events(&mut new, i, &input.bounds_in(i, child), axis);
            }
            new.sort_unstable_by(event_order);
            new
        })
    };
    let (new_below, new_above) = (fresh(&below_box), fresh(&above_box));
    // Step 5: every list split in order, the new events merged in.
    let mut below: [Vec<Event>; 3] = Default::default();
    let mut above: [Vec<Event>; 3] = Default::default();
    for axis in 0..3 {
        let (mut b, mut a) = (Vec::new(), Vec::new());
        for e in &events[axis] {
            match sides[e.object as usize] {
                Side::Below => b.push(*e),
                Side::Above => a.push(*e),
                Side::Both => {}
            }
        }
        below[axis] = merge(b, &new_below[axis]);
        above[axis] = merge(a, &new_above[axis]);
    }
    drop(events);
    let (n_below, n_above) =
        (objects_of(&below[0]).count(), objects_of(&above[0]).count());
    let me = out.split(plane.axis, plane.position);
    subtree(input, below, n_below, below_box, depth + 1, sides, out);
    out.above(me);
    subtree(input, above, n_above, above_box, depth + 1, sides, out);
}

/// Marks each object's side in `sides` from its events on the plane's
/// axis (the same rule as [`crate::events::side`]); returns the objects
/// the plane cuts.
fn classify(events: &[Event], plane: &Plane, sides: &mut [Side]) -> Vec<u32> {
    for e in events {
        sides[e.object as usize] = Side::Both;
    }
    let p = plane.position;
    for e in events {
        let side = &mut sides[e.object as usize];
        match e.kind {
            EventKind::End if e.position <= p => *side = Side::Below,
            EventKind::Start if e.position >= p => *side = Side::Above,
            EventKind::Planar => {
                *side = if e.position < p
                    || (e.position == p && plane.planar_below)
                {
                    Side::Below
                } else {
                    Side::Above
                }
            }
            _ => {}
        }
    }
    events
        .iter()
        .filter(|e| {
            e.kind == EventKind::Start && sides[e.object as usize] == Side::Both
        })
        .map(|e| e.object)
        .collect()
}

/// Two sorted lists as one.
fn merge(kept: Vec<Event>, new: &[Event]) -> Vec<Event> {
    if new.is_empty() {
        return kept;
    }
    let mut merged = Vec::with_capacity(kept.len() + new.len());
    let (mut i, mut j) = (0, 0);
    while i < kept.len() && j < new.len() {
        if event_order(&kept[i], &new[j]).is_le() {
            merged.push(kept[i]);
            i += 1;
        } else {
            merged.push(new[j]);
            j += 1;
        }
    }
    merged.extend_from_slice(&kept[i..]);
    merged.extend_from_slice(&new[j..]);
    merged
}
