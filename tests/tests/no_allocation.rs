//! Products, sandwiches, exp, log, inverses and integrator steps never touch the heap: a
//! counting global allocator sees no allocation while they run.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::hint::black_box;
use std::sync::atomic::{AtomicUsize, Ordering};

use ga_core::f64::g3::{Rotor, Vector};
use ga_rigid::dynamics::{omega_from_vector, Gravity, RigidBody, State};
use ga_rigid::integrators::{
    ClosedForm, DormandPrince, ExactFreeBody, ImplicitMidpoint, Integrator, LieDop853, LieRk4, Rk4,
    Splitting,
};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    // Whether this thread's allocations are counted: only the measured closure's, not the
    // test harness's main thread's, which may allocate while the test runs (a CI run once
    // counted one). Const-initialised without a destructor, so reading it never allocates.
    static COUNTING: Cell<bool> = const { Cell::new(false) };
}

// SAFETY: forwards to the system allocator unchanged, only counting calls.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if COUNTING.try_with(Cell::get).unwrap_or(false) {
            ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        }
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
    COUNTING.with(|c| c.set(true));
    f();
    COUNTING.with(|c| c.set(false));
    ALLOCATIONS.load(Ordering::SeqCst) - before
}

// One test function only: the harness runs tests on parallel threads, and another test's
// allocations would land in this one's count.
#[test]
fn products_exp_log_inverse_and_integrator_steps_do_not_allocate() {
    g3_operations();
    g4_operations();
    integrator_steps();
}

fn integrator_steps() {
    let free = RigidBody::new_unphysical([2.0, 1.0, 2.0 / 3.0]).unwrap();
    let symmetric = RigidBody::new([2.0, 2.0, 1.0]).unwrap();
    let heavy = RigidBody::new([1.0, 1.0, 0.5])
        .unwrap()
        .with_torque(Gravity {
            mass: 1.0,
            g: Vector::new(0.0, 0.0, -9.81),
            com_offset: Vector::new(0.0, 0.0, 0.5),
        });
    let state = State {
        rotor: Rotor::ONE,
        omega: omega_from_vector([0.4, -0.2, 1.1]),
    };
    let mut methods: Vec<Box<dyn Integrator>> = vec![
        Box::new(Rk4::new(0.01).unwrap()),
        Box::new(LieRk4::new(0.01).unwrap()),
        Box::new(ImplicitMidpoint::new(0.01).unwrap()),
        Box::new(Splitting::new(0.01).unwrap()),
        Box::new(DormandPrince::new(1e-9, 1e-12).unwrap()),
        Box::new(LieDop853::new(1e-10, 1e-10).unwrap()),
        Box::new(LieDop853::cayley(1e-10, 1e-10).unwrap()),
    ];
    let (mut exact, mut closed) = (ExactFreeBody::new(), ClosedForm::new());
    let count = allocations_during(|| {
        for method in methods.iter_mut() {
            for body in [&free, &heavy] {
                black_box(method.advance(body, 0.0, state, 0.5).unwrap());
            }
        }
        black_box(exact.advance(&free, 0.0, state, 3.0).unwrap());
        // Dense output: a sampled run and one step interpolated, into a caller's array.
        let mut dense = LieDop853::new(1e-10, 1e-10).unwrap();
        let times = [0.0, 0.1, 0.25, 0.5];
        let mut samples = [state; 4];
        let mut i = 0;
        for body in [&free, &heavy] {
            i = 0;
            black_box(
                dense
                    .dense_advance(body, 0.0, state, 0.5, &times, |_, s| {
                        samples[i] = s;
                        i += 1;
                    })
                    .unwrap(),
            );
            let step = dense.step(body, 0.0, state, 0.5).unwrap();
            black_box(step.at(0.5 * step.end_time()).unwrap());
        }
        black_box((&samples, i));
        black_box(closed.advance(&symmetric, 0.0, state, 3.0).unwrap());
    });
    assert_eq!(count, 0);
}

fn g3_operations() {
    use ga_core::f64::g3::*;
    let a = black_box(Multivector::from_array([
        0.1, 0.2, -0.3, 0.4, 0.5, -0.6, 0.7, 0.8,
    ]));
    let b = black_box(Multivector::from_array([
        -0.8, 0.7, 0.6, -0.5, 0.4, 0.3, 0.2, -0.1,
    ]));
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
