//! Mailboxing: an object that lies in several cells is met by a ray in
//! each of them; a mailbox remembers which objects this ray has already
//! tested, so it tests each one once.
//!
//! The classic mailbox stores a ray number in every object, which needs
//! writing into the scene while tracing. This one belongs to the ray: a
//! few slots, an object's slot chosen by its number (a *hashed* mailbox,
//! Benthin 2006). Two objects that share a slot may push each other out
//! and be tested twice — never wrongly skipped.

/// How many slots (a power of two).
pub const SLOTS: usize = 32;

/// The objects one ray has tested, as far as its slots remember.
#[derive(Clone, Debug)]
pub struct Mailbox {
    slots: [u32; SLOTS],
}

impl Default for Mailbox {
    fn default() -> Mailbox {
        Mailbox::new()
    }
}

impl Mailbox {
    /// An empty mailbox (for a new ray).
    pub fn new() -> Mailbox {
        Mailbox {
            slots: [u32::MAX; SLOTS],
        }
    }

    // ANCHOR: seen
    /// Has this ray already tested `object`? If not, it is remembered now
    /// (in its slot, in place of what was there).
    pub fn seen(&mut self, object: u32) -> bool {
        let slot = &mut self.slots[object as usize % SLOTS];
        if *slot == object {
            return true;
        }
        *slot = object;
        false
    }
    // ANCHOR_END: seen
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn remembers_until_pushed_out() {
        let mut m = Mailbox::new();
        assert!(!m.seen(3));
        assert!(m.seen(3));
        assert!(!m.seen(3 + SLOTS as u32)); // the same slot
        assert!(!m.seen(3)); // pushed out: tested again, never skipped
        assert!(!m.seen(u32::MAX - 1));
    }
}
