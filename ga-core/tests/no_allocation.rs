//! Products, sandwiches, exp and log never touch the heap: a counting global allocator sees
//! no allocation while they run.

use std::alloc::{GlobalAlloc, Layout, System};
use std::hint::black_box;
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

// SAFETY: forwards to the system allocator unchanged, only counting calls.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations_during(f: impl FnOnce()) -> usize {
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    f();
    ALLOCATIONS.load(Ordering::SeqCst) - before
}

// One test function only: the harness runs tests on parallel threads, and another test's
// allocations would land in this one's count.
#[test]
fn products_sandwiches_exp_log_and_inverse_do_not_allocate() {
    g3_operations();
    g4_operations();
}

fn g3_operations() {
    use ga_core::f64::g3::*;
    let a = black_box(Multivector::from_array([0.1, 0.2, -0.3, 0.4, 0.5, -0.6, 0.7, 0.8]));
    let b = black_box(Multivector::from_array([-0.8, 0.7, 0.6, -0.5, 0.4, 0.3, 0.2, -0.1]));
    let v = black_box(Vector::new(1.0, 2.0, 3.0));
    let bivector = black_box(Bivector::new(0.3, -0.2, 0.9));
    let count = allocations_during(|| {
        black_box(a * b);
        black_box(a ^ b);
        black_box(a | b);
        black_box(a.left_contraction(b));
        black_box(a.commutator(b));
        let r = bivector.exp();
        black_box(r.sandwich(v));
        black_box(r.log());
        black_box(r * r);
        black_box(a.inverse());
        black_box(v.reflect(Vector::E1));
    });
    assert_eq!(count, 0);
}

fn g4_operations() {
    use ga_core::f64::g4::*;
    let bivector = black_box(Bivector::new(0.3, -0.2, 0.9, 0.1, -0.4, 0.25));
    let count = allocations_during(|| {
        let r = bivector.exp();
        black_box(r.log());
        black_box(r * r);
        black_box(r.inverse());
        black_box(r.sandwich(Vector::E1));
        black_box(bivector.factor());
    });
    assert_eq!(count, 0);
}
