//! Which medium a ray is in: a stack of the transparent objects around it.

/// How many transparent objects can nest around a ray.
pub const MAX_NESTING: usize = 8;

// ANCHOR: media
/// The media around a ray, innermost last: the objects it is inside and
/// their indices of refraction, over the outside medium.
///
/// The lecture's rule "entering: n_θ outside, n_φ inside; leaving: flip
/// the normal, swap the indices" assumes the outside is the camera's
/// medium. An air bubble in water, or a glass ball in a water ball, breaks
/// it: leaving the bubble the ray enters water, not the camera's vacuum
/// the rule assumes. So each ray carries
/// the stack of objects it is inside: entering an object pushes it,
/// leaving pops it, and the index beyond a surface is whatever is on top
/// afterwards.
#[derive(Clone, Copy, Debug)]
pub struct Media {
    outside: f64,
    objects: [usize; MAX_NESTING],
    indices: [f64; MAX_NESTING],
    len: usize,
}

/// A ray crossing a surface: the indices on both sides and the media
/// beyond.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// n_θ, the index on the ray's side.
    pub n_theta: f64,
    /// n_φ, the index beyond the surface.
    pub n_phi: f64,
    /// The media a transmitted ray is in.
    pub beyond: Media,
    /// False if the crossing contradicts the stack: leaving an object the
    /// ray is not inside, entering one it is already inside, or nesting
    /// deeper than [`MAX_NESTING`]. The stack is then left as it was and
    /// the surface does not bend the ray (n_φ = n_θ).
    pub consistent: bool,
}

impl Media {
    /// A ray in the open, in a medium of index `outside` (the camera's).
    pub const fn new(outside: f64) -> Media {
        Media {
            outside,
            objects: [0; MAX_NESTING],
            indices: [0.0; MAX_NESTING],
            len: 0,
        }
    }

    /// The index of the medium the ray is in: the innermost object's, or
    /// the outside's.
    pub fn current(&self) -> f64 {
        match self.len {
            0 => self.outside,
            len => self.indices[len - 1],
        }
    }

    /// The objects the ray is inside, outermost first.
    pub fn objects(&self) -> &[usize] {
        &self.objects[..self.len]
    }

    /// Crossing the surface of `object` (index `ior`): into it if
    /// `entering`, else out of it.
    pub fn cross(&self, object: usize, ior: f64, entering: bool) -> Crossing {
        let n_theta = self.current();
        let inside = self.objects().iter().position(|&o| o == object);
        let beyond = match (entering, inside) {
            // Entering: push the object.
            (true, None) if self.len < MAX_NESTING => {
                let mut beyond = *self;
                beyond.objects[self.len] = object;
                beyond.indices[self.len] = ior;
                beyond.len += 1;
                Some(beyond)
            }
            // Leaving: take it out (usually the top; overlapping objects
            // can be left in another order).
            (false, Some(at)) => {
                let mut beyond = *self;
                beyond.objects.copy_within(at + 1..self.len, at);
                beyond.indices.copy_within(at + 1..self.len, at);
                beyond.len -= 1;
                Some(beyond)
            }
            _ => None,
        };
        match beyond {
            Some(beyond) => Crossing {
                n_theta,
                n_phi: beyond.current(),
                beyond,
                consistent: true,
            },
            None => Crossing {
                n_theta,
                n_phi: n_theta,
                beyond: *self,
                consistent: false,
            },
        }
    }
}
// ANCHOR_END: media

/// Two stacks are equal if they hold the same objects over the same
/// outside medium; slots above the top (left over from popped objects) do
/// not count.
impl PartialEq for Media {
    fn eq(&self, other: &Media) -> bool {
        self.outside == other.outside
            && self.objects() == other.objects()
            && self.indices[..self.len] == other.indices[..other.len]
    }
}
