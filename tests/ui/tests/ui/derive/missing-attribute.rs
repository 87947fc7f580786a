#[derive(ga_macros::Algebra)]
pub struct G3;

fn main() {}
