//! How tight a bounding volume is: of the rays that hit the bound, how
//! many miss the object (the wasted object tests), and what the bound
//! saves on average. (The counts are made by the chapter's figures
//! crate, on random lines: `ch08_figures::measure_tightness`.)

/// What `rays` random rays did with an object and its bound.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tightness {
    /// The rays shot.
    pub rays: u64,
    /// Rays that hit the bound.
    pub bound_hits: u64,
    /// Rays that hit the object.
    pub object_hits: u64,
    /// Rays that hit the bound but missed the object: object tests spent
    /// for nothing.
    pub wasted: u64,
    /// Rays that hit the object but missed the bound: hits a bounded object
    /// would lose. 0 for a correct bound.
    pub lost: u64,
}

impl Tightness {
    /// P(bound hit): the fraction of rays that hit the bound, so that pay
    /// for the object's test too.
    pub fn p_bound(&self) -> f64 {
        self.bound_hits as f64 / self.rays as f64
    }

    /// P(object hit): the fraction of rays that hit the object.
    pub fn p_object(&self) -> f64 {
        self.object_hits as f64 / self.rays as f64
    }

    /// P(object hit | bound hit): how tight the bound is (1 is a perfect
    /// fit). NaN if no ray hit the bound.
    pub fn p_object_given_bound(&self) -> f64 {
        (self.bound_hits - self.wasted) as f64 / self.bound_hits as f64
    }

    /// The fraction of bound hits that miss the object, 1 − P(object |
    /// bound). NaN if no ray hit the bound.
    pub fn wasted_fraction(&self) -> f64 {
        self.wasted as f64 / self.bound_hits as f64
    }

    // ANCHOR: expected_cost
    /// The average cost of a ray behind the bound, C_bound + P(bound hit)
    /// · C_object, in the units of the two costs. Without the bound every
    /// ray costs C_object.
    pub fn expected_cost(&self, c_bound: f64, c_object: f64) -> f64 {
        c_bound + self.p_bound() * c_object
    }

    /// C_object over the expected cost: above 1 the bound pays, below 1
    /// it costs more than it saves.
    pub fn speed_up(&self, c_bound: f64, c_object: f64) -> f64 {
        c_object / self.expected_cost(c_bound, c_object)
    }
    // ANCHOR_END: expected_cost
}
