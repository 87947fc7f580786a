#[derive(ga_macros::Algebra)]
#[algebra(metric = [1, 1, 1], scalar = f64, dimension = 3)]
pub struct G3;

fn main() {}
