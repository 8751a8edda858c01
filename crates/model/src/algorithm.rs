//! A run of an algorithm as data: what the library offers, the inputs being
//! picked and the recorded trace being walked, what each step shows, and the
//! questions it asks. The app's algorithm panel draws these.

pub mod frame;
pub mod library;
pub mod question_sets;
pub mod quiz;
pub mod run;
pub mod session;
