ga_macros::algebra! {
    pub mod g3 {
        signature: (0x3, 0, 0),
    }
}

fn main() {}
