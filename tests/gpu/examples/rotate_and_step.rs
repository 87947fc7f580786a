//! The emitted G3 WGSL (`ga_core::f32::g3::WGSL`) at work in two compute shaders, each
//! checked against the same computation on the CPU in f32:
//!
//! 1. 10^6 vectors rotated by one rotor with `sandwich_even_vector` (the CPU side is
//!    `Rotor::sandwich`);
//! 2. 10^5 free rigid bodies stepped with the explicit splitting of Dullweber, Leimkuhler
//!    and McLachlan (ga-rigid's `splitting` method): the flow of `m_k^2 / 2 i_k` turns the
//!    body momentum `m` about `e_k` and the body with it, written here on the emitted
//!    rotor functions: with `q = exp(theta/2 I e_k)`, `theta = tau m_k / i_k`, the flow is
//!    `m <- q m ~q` and `R <- R ~q` (so `L = R m ~R` is kept exactly), composed as
//!    `e1(h/2) e2(h/2) e3(h) e2(h/2) e1(h/2)`.
//!
//! Prints the device, the timings (the GPU's includes the upload, the dispatch and the
//! read-back, not the pipeline's creation; the first dispatch on lavapipe also compiles
//! the kernel's machine code, so two dispatches are timed) and the largest differences.
//! Without a Vulkan device it says so and exits 0.
//!
//! `cargo run --release -p ga-gpu-tests --example rotate_and_step`

use std::time::Instant;

use ga_core::f32::g3::*;
use ga_gpu_tests::{random_inputs, Gpu};
use wgpu::util::DeviceExt;

/// Vectors rotated in part 1.
const VECTORS: usize = 1_000_000;
/// Bodies stepped in part 2.
const BODIES: usize = 100_000;
/// Steps of part 2, all in one dispatch.
const STEPS: u32 = 100;
/// The step of part 2.
const H: f32 = 0.01;

/// Part 1's kernel: one vector per invocation, rotated in place.
const ROTATE: &str = r"
@group(0) @binding(0) var<storage, read> rotor: Rotor;
@group(0) @binding(1) var<storage, read_write> points: array<Vector>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x + id.y * 65535u * 64u;
    if (i < arrayLength(&points)) {
        points[i] = sandwich_even_vector(rotor, points[i]);
    }
}
";

/// Part 2's kernel: one body per invocation, `STEPS` steps of `H`. `moments` holds the
/// principal moments `i1, i2, i3` per body; `state` the rotor (4 floats) and the body
/// momentum (3 floats) per body.
const STEP: &str = r"
@group(0) @binding(0) var<storage, read> moments: array<f32>;
@group(0) @binding(1) var<storage, read_write> state: array<f32>;

// I e_k for k = 0, 1, 2: e23, -e13, e12.
fn dual_axis(k: u32, a: f32) -> Bivector {
    if (k == 0u) {
        return Bivector(0.0, 0.0, a);
    } else if (k == 1u) {
        return Bivector(0.0, -a, 0.0);
    }
    return Bivector(a, 0.0, 0.0);
}

fn component(v: Vector, k: u32) -> f32 {
    if (k == 0u) {
        return v.e1;
    } else if (k == 1u) {
        return v.e2;
    }
    return v.e3;
}

struct Body {
    r: Rotor,
    m: Vector,
}

// The exact flow of m_k^2 / 2 i_k for time tau.
fn axis_flow(b: Body, i: Vector, k: u32, tau: f32) -> Body {
    let theta = tau * component(b.m, k) / component(i, k);
    let q = exp_bivector(dual_axis(k, 0.5 * theta));
    return Body(geometric_even_even(b.r, reverse_even(q)), sandwich_even_vector(q, b.m));
}

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let n = id.x;
    if (n >= arrayLength(&moments) / 3u) {
        return;
    }
    let i = Vector(moments[3u * n], moments[3u * n + 1u], moments[3u * n + 2u]);
    let o = 7u * n;
    var b = Body(
        Rotor(state[o], state[o + 1u], state[o + 2u], state[o + 3u]),
        Vector(state[o + 4u], state[o + 5u], state[o + 6u]),
    );
    let h = H;
    for (var s = 0u; s < STEPS; s++) {
        b = axis_flow(b, i, 0u, 0.5 * h);
        b = axis_flow(b, i, 1u, 0.5 * h);
        b = axis_flow(b, i, 2u, h);
        b = axis_flow(b, i, 1u, 0.5 * h);
        b = axis_flow(b, i, 0u, 0.5 * h);
    }
    state[o] = b.r.s;
    state[o + 1u] = b.r.e12;
    state[o + 2u] = b.r.e13;
    state[o + 3u] = b.r.e23;
    state[o + 4u] = b.m.e1;
    state[o + 5u] = b.m.e2;
    state[o + 6u] = b.m.e3;
}
";

/// One compute kernel ready to dispatch: `WGSL` plus the kernel, bindings 0 (read) and 1
/// (read and write, copied back).
struct Kernel {
    pipeline: wgpu::ComputePipeline,
}

impl Kernel {
    fn new(gpu: &Gpu, kernel: &str) -> Kernel {
        let module = gpu
            .device()
            .create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("example"),
                source: wgpu::ShaderSource::Wgsl(format!("{WGSL}\n{kernel}").into()),
            });
        let pipeline = gpu
            .device()
            .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some("example"),
                layout: None,
                module: &module,
                entry_point: Some("main"),
                compilation_options: Default::default(),
                cache: None,
            });
        Kernel { pipeline }
    }

    /// Uploads `input` and `data`, runs `groups` workgroups (x, y) and returns `data` as
    /// the kernel left it.
    fn run(&self, gpu: &Gpu, input: &[u8], data: &[u8], groups: (u32, u32)) -> Vec<u8> {
        let device = gpu.device();
        let input = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("input"),
            contents: input,
            usage: wgpu::BufferUsages::STORAGE,
        });
        let storage = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("data"),
            contents: data,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        });
        let readback = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: data.len() as u64,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &self.pipeline.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: input.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: storage.as_entire_binding(),
                },
            ],
        });
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            pass.dispatch_workgroups(groups.0, groups.1, 1);
        }
        encoder.copy_buffer_to_buffer(&storage, 0, &readback, 0, data.len() as u64);
        gpu.queue().submit([encoder.finish()]);
        readback.map_async(wgpu::MapMode::Read, .., |r| {
            r.expect("the read-back buffer maps");
        });
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .expect("the device finishes");
        let bytes = readback
            .get_mapped_range(..)
            .expect("the mapped range")
            .to_vec();
        readback.unmap();
        bytes
    }
}

/// Runs `kernel` twice (the first dispatch on lavapipe also compiles it), printing both
/// times, and returns the second result.
fn timed(gpu: &Gpu, kernel: &Kernel, input: &[u8], data: &[u8], groups: (u32, u32)) -> Vec<u8> {
    let t0 = Instant::now();
    let _ = kernel.run(gpu, input, data, groups);
    let first = t0.elapsed().as_secs_f64();
    let t1 = Instant::now();
    let out = kernel.run(gpu, input, data, groups);
    let second = t1.elapsed().as_secs_f64();
    println!("  GPU: {first:.3} s first dispatch (with the driver's compile), {second:.3} s second (upload, dispatch, read-back)");
    out
}

/// Distance in units in the last place between two floats of the same sign (and through
/// zero otherwise).
fn ulps(a: f32, b: f32) -> u32 {
    // The bit patterns of finite floats, mapped to a line that is monotone in the value.
    let key = |x: f32| {
        let bits = x.to_bits() as i32;
        if bits < 0 {
            i32::MIN - bits
        } else {
            bits
        }
    };
    key(a).abs_diff(key(b))
}

/// Part 1: the rotation of 10^6 vectors.
fn rotate(gpu: &Gpu) {
    println!("1. {VECTORS} vectors rotated by one rotor (sandwich_even_vector)");
    let rotor = Rotor::from_axis_angle(Vector::new(0.36, 0.48, 0.8), 1.1);
    // random_inputs(0, n, _) gives 2n floats: three per vector.
    let points: Vec<Vector> = random_inputs(0, 3 * VECTORS / 2, 11)
        .chunks_exact(3)
        .map(|c| Vector::new(c[0], c[1], c[2]))
        .collect();
    let t0 = Instant::now();
    let cpu: Vec<Vector> = points.iter().map(|&p| rotor.sandwich(p)).collect();
    let cpu_time = t0.elapsed().as_secs_f64();
    println!("  CPU: {cpu_time:.3} s (one thread)");
    // 65535 workgroups at most per dimension: the rest in y.
    let groups = points.len().div_ceil(64) as u32;
    let grid = (groups.min(65535), groups.div_ceil(65535));
    let kernel = Kernel::new(gpu, ROTATE);
    let bytes = timed(
        gpu,
        &kernel,
        bytemuck::bytes_of(&rotor),
        bytemuck::cast_slice(&points),
        grid,
    );
    let gpu_out: &[Vector] = bytemuck::cast_slice(&bytes);
    let (mut max_abs, mut max_rel, mut max_ulps) = (0f32, 0f32, 0u32);
    for ((g, c), p) in gpu_out.iter().zip(&cpu).zip(&points) {
        for (x, y) in g.to_array().into_iter().zip(c.to_array()) {
            max_abs = max_abs.max((x - y).abs());
            // Relative to the vector's length, which the rotation keeps: a component that
            // cancels to near zero would make a per-component relative figure meaningless.
            max_rel = max_rel.max((x - y).abs() / p.norm().max(f32::MIN_POSITIVE));
            max_ulps = max_ulps.max(ulps(x, y));
        }
    }
    println!(
        "  largest difference: {max_abs:.2e} absolute, {:.2} eps of |x|, {max_ulps} ulps (any component)",
        max_rel / f32::EPSILON
    );
}

/// The flow of `m_k^2 / 2 i_k` for `tau` on the CPU: the shader's `axis_flow`.
fn axis_flow(r: &mut Rotor, m: &mut Vector, i: [f32; 3], k: usize, tau: f32) {
    let theta = tau * m.to_array()[k] / i[k];
    let a = 0.5 * theta;
    let plane = match k {
        0 => Bivector::new(0.0, 0.0, a),
        1 => Bivector::new(0.0, -a, 0.0),
        _ => Bivector::new(a, 0.0, 0.0),
    };
    let q = plane.exp();
    *r *= q.reverse();
    *m = q.sandwich(*m);
}

/// Part 2: 10^5 free rigid bodies, `STEPS` splitting steps each.
fn step(gpu: &Gpu) {
    println!("2. {BODIES} free rigid bodies, {STEPS} DLM splitting steps of h = {H}");
    let noise = random_inputs(3, BODIES, 23);
    let mut moments = Vec::with_capacity(BODIES);
    let mut state = Vec::with_capacity(7 * BODIES);
    for c in noise.chunks_exact(16) {
        // Moments in [1, 3], a random unit rotor, a body momentum in [-1, 1]^3.
        moments.push([2.0 + c[0], 2.0 + c[1], 2.0 + c[2]]);
        let r = Rotor::new(c[3], c[4], c[5], c[6]).normalized();
        state.extend_from_slice(&r.to_array());
        state.extend_from_slice(&[c[7], c[8], c[9]]);
    }
    let t0 = Instant::now();
    let mut cpu = state.clone();
    for (body, i) in cpu.chunks_exact_mut(7).zip(&moments) {
        let mut r = Rotor::new(body[0], body[1], body[2], body[3]);
        let mut m = Vector::new(body[4], body[5], body[6]);
        for _ in 0..STEPS {
            axis_flow(&mut r, &mut m, *i, 0, 0.5 * H);
            axis_flow(&mut r, &mut m, *i, 1, 0.5 * H);
            axis_flow(&mut r, &mut m, *i, 2, H);
            axis_flow(&mut r, &mut m, *i, 1, 0.5 * H);
            axis_flow(&mut r, &mut m, *i, 0, 0.5 * H);
        }
        body[..4].copy_from_slice(&r.to_array());
        body[4..].copy_from_slice(&m.to_array());
    }
    let cpu_time = t0.elapsed().as_secs_f64();
    println!("  CPU: {cpu_time:.3} s (one thread)");
    let constants = format!("const STEPS: u32 = {STEPS}u;\nconst H: f32 = {H:?};\n");
    let kernel = Kernel::new(gpu, &format!("{constants}{STEP}"));
    let groups = (BODIES.div_ceil(64) as u32, 1);
    let bytes = timed(
        gpu,
        &kernel,
        bytemuck::cast_slice(&moments),
        bytemuck::cast_slice(&state),
        groups,
    );
    let gpu_out: &[f32] = bytemuck::cast_slice(&bytes);
    let (mut rotor_diff, mut momentum_diff) = (0f32, 0f32);
    for (g, c) in gpu_out.chunks_exact(7).zip(cpu.chunks_exact(7)) {
        let (gr, cr) = (body(g).0, body(c).0);
        rotor_diff = rotor_diff.max((gr - cr).norm());
        let (gm, cm) = (body(g).1, body(c).1);
        momentum_diff = momentum_diff.max((gm - cm).norm() / cm.norm());
    }
    println!(
        "  largest difference GPU - CPU: rotor {rotor_diff:.2e} (|R| = 1), body momentum {momentum_diff:.2e} of |m|"
    );
    for (side, end) in [("GPU", gpu_out), ("CPU", &cpu[..])] {
        let (spin, unit) = drift(&state, end);
        println!("  {side} drift over the run: L = R m ~R {spin:.2e} of |L|, |R| - 1 {unit:.2e}");
    }
}

/// The rotor and body momentum of one body's 7 floats.
fn body(s: &[f32]) -> (Rotor, Vector) {
    (
        Rotor::new(s[0], s[1], s[2], s[3]),
        Vector::new(s[4], s[5], s[6]),
    )
}

/// The largest relative change of the space momentum `L = R m ~R` (which every sub-flow
/// keeps exactly) and the largest `||R| - 1|` from `start` to `end`. Both grow about
/// linearly in the steps in f32: a body's turn angles change slowly, so the rounding of
/// its `cos` and `sin` and of the products near the identity repeats with the same sign
/// step after step (normalizing `q` after `exp` did not help: it rounds the same way).
fn drift(start: &[f32], end: &[f32]) -> (f32, f32) {
    let (mut spin, mut unit) = (0f32, 0f32);
    for (s, e) in start.chunks_exact(7).zip(end.chunks_exact(7)) {
        let ((r0, m0), (r1, m1)) = (body(s), body(e));
        let l0 = r0.sandwich(m0);
        spin = spin.max((r1.sandwich(m1) - l0).norm() / l0.norm());
        unit = unit.max((r1.norm() - 1.0).abs());
    }
    (spin, unit)
}

fn main() {
    let gpu = match Gpu::vulkan() {
        Ok(gpu) => gpu,
        Err(why) => {
            println!("No Vulkan device ({why}): nothing run.");
            return;
        }
    };
    println!("Device: {}", gpu.description);
    rotate(&gpu);
    step(&gpu);
}
