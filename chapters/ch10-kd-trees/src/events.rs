//! The SAH builders' shared step: a node's candidate planes as sorted
//! *events* (where an object's box starts, ends, or lies flat), swept
//! once per axis to find the cheapest plane.
use std::cmp::Ordering;

use raystep_core::Aabb;

use crate::KdCosts;

/// What happens at an event's position, in the order events at the same
/// position are swept: boxes ending there first, then flat ones, then
/// boxes starting there.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum EventKind {
    /// An object's box ends at the position.
    End,
    /// An object's box is flat there (min = max on this axis).
    Planar,
    /// An object's box starts at the position.
    Start,
}

/// One candidate plane on one axis, and which object puts it there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Event {
    /// Where on the axis.
    pub position: f64,
    /// What the object's box does there.
    pub kind: EventKind,
    /// The object.
    pub object: u32,
}

/// The order of a sweep: position, then kind, then object (a total
/// order, so both builders see the same list).
pub fn event_order(a: &Event, b: &Event) -> Ordering {
    a.position
        .total_cmp(&b.position)
        .then(a.kind.cmp(&b.kind))
        .then(a.object.cmp(&b.object))
}

/// Object `object`'s events on `axis`, for its box `b` in the node.
pub fn push_events(
    events: &mut Vec<Event>, object: u32, b: &Aabb, axis: usize,
) {
    let (min, max) = (b.min[axis], b.max[axis]);
    if min == max {
        events.push(Event {
            position: min,
            kind: EventKind::Planar,
            object,
        });
    } else {
        events.push(Event {
            position: min,
            kind: EventKind::Start,
            object,
        });
        events.push(Event {
            position: max,
            kind: EventKind::End,
            object,
        });
    }
}

/// The cheapest plane of a node.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// 0, 1 or 2.
    pub axis: usize,
    /// Where it cuts.
    pub position: f64,
    /// Do objects lying flat in the plane go below it (else above)?
    pub planar_below: bool,
    /// Its SAH cost.
    pub cost: f64,
    /// Objects below it, and above it (flat ones counted on their side).
    pub counts: (usize, usize),
}

// ANCHOR: sweep
/// Sweeps one axis's sorted events of a node holding `count` objects and
/// offers every plane strictly inside the node to `best` (the cheapest so
/// far; ties keep the earlier plane).
pub fn sweep(
    events: &[Event], axis: usize, count: usize, node: &Aabb, costs: &KdCosts,
    best: &mut Option<Plane>,
) {
    // Step 1: before the first plane, every object is above.
    let (mut below, mut above) = (0, count);
    let mut i = 0;
    while i < events.len() {
        let position = events[i].position;
        // Step 2: how many boxes end, lie flat, and start here.
        let mut tally = [0usize; 3];
        while i < events.len() && events[i].position == position {
            tally[events[i].kind as usize] += 1;
            i += 1;
        }
        let [ends, planar, starts] = tally;
        // Step 3: boxes ending here, and flat ones, leave the side above.
        above -= ends + planar;
        // Step 4: the plane's cost, flat objects on either side.
        if node.min[axis] < position && position < node.max[axis] {
            for (planar_below, counts) in [
                (true, (below + planar, above)),
                (false, (below, above + planar)),
            ] {
                // Exercise 1's cost (in student mode, the student's own).
                let cost = crate::split_cost(
                    node, axis, position, counts.0, counts.1, costs,
                );
                if best.is_none_or(|b| cost < b.cost) {
                    *best = Some(Plane {
                        axis,
                        position,
                        planar_below,
                        cost,
                        counts,
                    });
                }
            }
        }
        // Step 5: past the plane, flat boxes and starting ones are below.
        below += planar + starts;
    }
}
// ANCHOR_END: sweep

/// Which child an object goes to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Below the plane only.
    Below,
    /// Above it only.
    Above,
    /// Cut by it: both.
    Both,
}

/// The side of an object with box `b` (in the node) for `plane`: a box
/// touching the plane from one side stays on that side.
pub fn side(b: &Aabb, plane: &Plane) -> Side {
    let (min, max) = (b.min[plane.axis], b.max[plane.axis]);
    let p = plane.position;
    if min == p && max == p {
        if plane.planar_below {
            Side::Below
        } else {
            Side::Above
        }
    } else if max <= p {
        Side::Below
    } else if min >= p {
        Side::Above
    } else {
        Side::Both
    }
}

/// The objects of the two children: each object (its box in the node
/// from `boxes`, in the same order) to its [`side`] of `plane`, to both
/// if the plane cuts it.
pub fn sides(
    objects: &[u32], boxes: impl IntoIterator<Item = Aabb>, plane: &Plane,
) -> (Vec<u32>, Vec<u32>) {
    let (mut below, mut above) = (Vec::new(), Vec::new());
    for (&i, b) in objects.iter().zip(boxes) {
        match side(&b, plane) {
            Side::Below => below.push(i),
            Side::Above => above.push(i),
            Side::Both => {
                below.push(i);
                above.push(i);
            }
        }
    }
    (below, above)
}

/// The node's two children's boxes.
pub fn children(node: &Aabb, axis: usize, position: f64) -> (Aabb, Aabb) {
    let (mut below, mut above) = (*node, *node);
    below.max[axis] = position;
    above.min[axis] = position;
    (below, above)
}

/// Is the cheapest plane worth it? Only if it costs less than testing
/// every object here (a leaf).
pub fn worth_splitting(plane: &Plane, count: usize, costs: &KdCosts) -> bool {
    plane.cost < count as f64 * costs.intersection
}
