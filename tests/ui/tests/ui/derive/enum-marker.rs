#[derive(ga_macros::Algebra)]
#[algebra(metric = [1, 1, 1])]
pub enum G3 {}

fn main() {}
