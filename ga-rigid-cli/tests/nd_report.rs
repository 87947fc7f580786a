//! The report's four-dimensional part, quick size: the observed orders of the fixed-step
//! methods (the orders their papers prove), the symmetric body's closed form against
//! `lie-dop853` at tol 1e-13, the reference body's reference against the published values
//! of docs/references.md, the unstable double rotation's growth, `nd_results.csv` read
//! back, and the diagrams' legends.

use std::sync::OnceLock;

use ga_rigid_cli::report::nd::{
    nd_csv, nd_order, nd_scenes, nd_svg, run_nd, NdMethod, NdSceneResult,
};
use ga_rigid_cli::report::{Order, Size};

/// The quick four-dimensional report, run once for every test here.
fn report() -> &'static [NdSceneResult] {
    static REPORT: OnceLock<Vec<NdSceneResult>> = OnceLock::new();
    REPORT.get_or_init(|| {
        let scenes = run_nd(Size::Quick, &mut |_, _| {}).unwrap();
        for scene in &scenes {
            eprintln!("{}: check {:?}", scene.name, scene.check);
            for row in &scene.rows {
                eprintln!(
                    "  {:11} {:.3e} steps {:6} {:?} us {:?}",
                    row.method.name(),
                    row.param,
                    row.steps,
                    row.errors,
                    row.time_us()
                );
            }
        }
        scenes
    })
}

/// RK4 and RKMK4 show order four, the midpoint rule and the splitting order two, on every
/// scene: the fitted slope within 0.3.
#[test]
fn fixed_step_methods_show_their_orders_in_four_dimensions() {
    for scene in report() {
        for (method, expected) in [
            (NdMethod::Rk4, 4.0),
            (NdMethod::LieRk4, 4.0),
            (NdMethod::Midpoint, 2.0),
            (NdMethod::Splitting, 2.0),
        ] {
            match nd_order(scene, method) {
                Order::Fitted(p, n) => assert!(
                    (p - expected).abs() <= 0.3,
                    "{}: {} shows order {p:.2} over {n} runs",
                    scene.name,
                    method.name()
                ),
                Order::TooFewPoints(n) => panic!(
                    "{}: {} has {n} runs to fit an order to",
                    scene.name,
                    method.name()
                ),
            }
        }
    }
}

/// The scene of `report()` whose name starts with `prefix`.
fn scene(prefix: &str) -> &'static NdSceneResult {
    report()
        .iter()
        .find(|s| s.name.starts_with(prefix))
        .unwrap_or_else(|| panic!("no scene {prefix}"))
}

/// On the symmetric body the closed form and `lie-dop853` at tol 1e-13 agree to 1e-11 rad
/// over the run: the reference check, and the closed form's own row (measured against
/// `lie-dop853`, never against itself).
#[test]
fn the_closed_form_agrees_with_the_reference_on_the_symmetric_body() {
    let symmetric = scene("4D symmetric");
    assert!(symmetric.check.primary.contains("closed form"));
    assert!(
        symmetric.check.errors.attitude_max < 1e-11,
        "{:?}",
        symmetric.check
    );
    assert!(
        symmetric.check.errors.omega_max < 1e-11,
        "{:?}",
        symmetric.check
    );
    let closed: Vec<_> = symmetric
        .rows
        .iter()
        .filter(|r| r.method == NdMethod::ClosedForm)
        .collect();
    assert_eq!(closed.len(), 1);
    assert_eq!(closed[0].reference, NdMethod::LieDop853);
    let errors = closed[0].errors.unwrap();
    assert!(errors.attitude_max < 1e-11, "{errors:?}");
    // Only the symmetric body has a closed form.
    for other in report().iter().filter(|s| s.name != symmetric.name) {
        assert!(other.rows.iter().all(|r| r.method != NdMethod::ClosedForm));
    }
}

/// The reference body's reference, `lie-dop853` at tol 1e-13, reproduces the published
/// R(10) and Omega_B(10) of docs/references.md to their 12 decimals, and agrees with RK4
/// at a fine step over the whole run.
#[test]
fn the_reference_body_reproduces_the_published_state_at_t_10() {
    let body = scene("4D asymmetric");
    let (published, dr, dw) = body.check.published.expect("published values");
    assert_eq!(published.t, 10.0);
    assert!(dr < 1e-11 && dw < 1e-11, "{dr:e} {dw:e}");
    assert!(body.check.errors.attitude_max < 1e-11, "{:?}", body.check);
    assert!(body.check.secondary.starts_with("rk4"));
}

/// The double rotation 2 e12 + e34 of the body (0.5, 2.0, 0.9, 1.4) is unstable: the
/// 1e-3 perturbation grows past 1 (a thousandfold), at first like `exp(0.533 t)`, the
/// linearisation's rate; its two references still agree to 1e-11 rad.
#[test]
fn the_double_rotation_near_the_middle_planes_is_unstable() {
    let unstable = scene("4D unstable");
    let (start, largest, at) = unstable.check.growth.expect("a perturbation to follow");
    assert!((start - 2e-3).abs() < 1e-15, "{start}");
    assert!(
        largest > 1.0 && largest / start > 500.0,
        "{largest} at {at}"
    );
    assert!(
        unstable.check.errors.attitude_max < 1e-11,
        "{:?}",
        unstable.check
    );

    // The early growth rate, on lie-dop853 at tol 1e-13 from the scene's start.
    let scenes = nd_scenes().unwrap();
    let scene = scenes.iter().find(|s| s.name == unstable.name).unwrap();
    let off = |omega: ga_core::f64::g4::Bivector| {
        let mut rest = omega;
        rest[0] = 0.0;
        rest[5] = 0.0;
        rest.norm()
    };
    let mut method = ga_rigid::nd::LieDop853::new(1e-13, 1e-13).unwrap();
    use ga_rigid::nd::Integrator as _;
    let t = 8.0;
    let later = method.advance(&scene.body, 0.0, scene.initial, t).unwrap();
    let rate = (off(later.omega) / off(scene.initial.omega)).ln() / t;
    assert!((rate - 0.533).abs() < 0.1, "growth rate {rate}");

    // Without the perturbation the double rotation is steady.
    let mut steady = scene.initial;
    steady.omega = ga_core::f64::g4::Bivector::new(2.0, 0.0, 0.0, 0.0, 0.0, 1.0);
    let mut method = ga_rigid::nd::LieDop853::new(1e-13, 1e-13).unwrap();
    let end = method.advance(&scene.body, 0.0, steady, 20.0).unwrap();
    assert!((end.omega - steady.omega).norm() < 1e-12, "{:?}", end.omega);
}

/// `nd_results.csv` as written, read back: one row per measurement, in order, each number
/// the measurement's own (`{:e}` reads back to the same f64).
#[test]
fn nd_results_csv_reads_back_as_the_measurements() {
    let scenes = report();
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("ga-rigid-nd-report");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("nd_results.csv");
    std::fs::write(&path, nd_csv(scenes)).unwrap();
    let written = std::fs::read_to_string(&path).unwrap();
    let mut lines = written.lines();
    // The columns spelled out here, not read from `ND_CSV_HEADER` (which the writer also
    // prints, so comparing the two would check nothing): a renamed, dropped or reordered
    // column fails.
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(
        header,
        [
            "scene",
            "method",
            "param_kind",
            "param",
            "steps",
            "repeats",
            "time_median_us",
            "err_attitude_max",
            "energy_drift_rel_max",
            "reference",
            "status"
        ]
    );
    let column = |name: &str| header.iter().position(|c| *c == name).unwrap();
    let number = |cells: &[&str], name: &str| cells[column(name)].parse::<f64>().unwrap();
    let mut count = 0;
    for scene in scenes {
        for row in &scene.rows {
            let line = lines.next().expect("a line per measurement");
            let cells: Vec<&str> = line.split(',').collect();
            assert_eq!(cells.len(), header.len(), "{line}");
            assert_eq!(cells[column("scene")], scene.name);
            assert_eq!(cells[column("method")], row.method.name());
            assert_eq!(cells[column("param_kind")], row.param_kind());
            assert_eq!(number(&cells, "param"), row.param);
            assert_eq!(cells[column("steps")].parse::<u64>().unwrap(), row.steps);
            assert_eq!(cells[column("reference")], row.reference.name());
            assert_eq!(cells[column("status")], "ok", "{line}");
            let timing = row.timing.unwrap();
            assert_eq!(
                cells[column("repeats")].parse::<usize>().unwrap(),
                timing.repeats
            );
            assert_eq!(
                number(&cells, "time_median_us"),
                timing.median.as_secs_f64() * 1e6
            );
            let errors = row.errors.unwrap();
            assert_eq!(number(&cells, "err_attitude_max"), errors.attitude_max);
            assert_eq!(number(&cells, "energy_drift_rel_max"), errors.energy_max);
            count += 1;
        }
    }
    assert_eq!(lines.next(), None);
    assert!(count > 60, "{count} rows");
}

/// Each diagram's legend names each of the scene's methods exactly once (a name is a
/// `<text>` element of its own), and the symmetric body's names all seven.
#[test]
fn each_plot_names_every_method_in_its_legend_exactly_once() {
    for scene in report() {
        let svg = nd_svg(scene).unwrap();
        let mut shown = 0;
        for method in NdMethod::ALL {
            let runs = scene.rows.iter().any(|r| r.method == method);
            let tag = format!("\n{}\n</text>", method.name());
            assert_eq!(
                svg.matches(&tag).count(),
                usize::from(runs),
                "{}: {}",
                scene.name,
                method.name()
            );
            shown += usize::from(runs);
        }
        let expected = if scene.name.starts_with("4D symmetric") {
            7
        } else {
            6
        };
        assert_eq!(shown, expected, "{}", scene.name);
    }
}

/// The page's section shows a diagram, a check line and an order table per scene.
#[test]
fn the_page_has_a_four_dimensions_section() {
    let mut page = String::new();
    ga_rigid_cli::report::nd::nd_section(&mut page, report());
    assert!(page.contains("<h2>Four dimensions</h2>"));
    assert!(page.contains("nd_results.csv"));
    for (i, scene) in report().iter().enumerate() {
        let svg = ga_rigid_cli::report::nd::nd_svg_name(i, &scene.name);
        assert!(page.contains(&format!("<img src=\"{svg}\"")), "{svg}");
    }
    assert_eq!(page.matches("<b>Check:</b>").count(), 3);
    assert_eq!(
        page.matches("<b>Check against published values:</b>")
            .count(),
        1
    );
    assert_eq!(page.matches("<b>Instability:</b>").count(), 1);
    assert_eq!(page.matches("<th>observed order</th>").count(), 3);
}

/// The command checks the 4D files with the others before any run: a directory where
/// `nd_results.csv` or a 4D diagram goes is refused with status 2, and nothing is written.
#[test]
fn the_command_refuses_an_obstacle_at_a_4d_file_before_the_suite() {
    let base = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("ga-rigid-nd-obstacle");
    let _ = std::fs::remove_dir_all(&base);
    let dir = base.join("r");
    std::fs::create_dir_all(&dir).unwrap();
    let diagram = ga_rigid_cli::report::nd::nd_svg_name(0, &nd_scenes().unwrap()[0].name);
    for name in ["nd_results.csv", diagram.as_str()] {
        std::fs::create_dir(dir.join(name)).unwrap();
        let started = std::time::Instant::now();
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_ga-rigid"))
            .args(["report", "--quick", "--out", "r"])
            .current_dir(&base)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(
            stderr.contains(&format!("r/{name} is a directory")),
            "{stderr}"
        );
        assert!(
            started.elapsed().as_secs() < 20,
            "refused only after the suite"
        );
        let names: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        assert_eq!(names, [name], "files written before the refusal");
        std::fs::remove_dir(dir.join(name)).unwrap();
    }
}
