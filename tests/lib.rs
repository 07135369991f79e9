//! Helpers shared by the cross-chapter tests (none yet).
