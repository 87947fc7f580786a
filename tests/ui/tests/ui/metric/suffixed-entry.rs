ga_macros::algebra! {
    pub mod g3 {
        metric: [1, -1u8, 0],
    }
}

fn main() {}
