//! gjk2d's error against its run time, side by side with parry2d.
//!
//! ```text
//! cargo run --release --example report              # the default run
//! cargo run --release --example report -- --quick   # CI's smoke run: fewer cases and repeats
//! cargo run --release --example report -- --long    # 4x the cases, more repeats
//! cargo run --release --example report -- --cases my-cases.txt --out report
//! cargo run --release --example report -- --only poly64,circle_circle --reps 61
//! ```
//!
//! Every scene family is generated from a fixed seed. All inputs are f32 values, so the
//! f32 and f64 runs (and parry2d / parry2d-f64) read identical shapes, and one exact
//! answer serves them all. Exact answers come from `gjk2d-oracle` (rational arithmetic,
//! correctly rounded to f64). Ellipses are beyond the oracle: the ellipse-vs-circle
//! family is answered by Eberly's robust point-to-ellipse distance (bisection to the
//! last bit in f64), an independent method accurate to a few f64 ulps of the size.
//!
//! Errors are relative to the pair's size L (the larger bounding radius about the
//! vertex mean); for rays L = max(bounding radius, distance from the ray origin to the
//! shape's center); for casts L is the pair's plus the motion's length. A verdict counts as wrong only when the exact margin exceeds
//! 8 eps L (eps of the precision under test): closer cases are too close to call.
//!
//! Writes `report.md` (the table, date, machine), `sweep.csv` and `sweep.svg`
//! (error against time per query as settings vary) to `--out` (default
//! `target/report/`, so a run leaves the checkout clean; `--out report` refreshes
//! the committed copy).

mod case_files;
mod cases;
mod families;
mod judge;
mod ours;
mod parry;
mod run;
mod sweep;
mod tables;
mod timing;
mod warm;

use case_files::{load_cases, save_cases};
use families::generate;
use run::{max_vertices, run_family};
use std::time::Instant;
use sweep::{sweep, write_sweep};
use tables::{machine, md_table, plain_table, stability, table_rows, targets, today, HEADER};

/// What the warm-starting table measures.
const WARM_NOTE: &str = "The same 16,384 pairs of 8-gons (placed as poly8's, about half overlapping) asked step after step, B moved by at most 1% of its size and turned by at most 1 degree a step: the cold queries, and the `_cached` ones with a `PairCache` a pair kept from step to step, timed in turn (a step a pass, each pair once, median over the passes; cached / cold is the median of the per-pass ratios). Iterations are the queries' own counts (0 where the cache alone decided), averaged over 8 checked steps after the first, where both answered; a cached answer differs where its verdict does, or its value (the distance beyond both error bounds; the depth, or a manifold's least separation, by a bit).";

fn main() {
    let mut scale = 4.0;
    let mut reps = 31;
    let mut mode = "default";
    let mut files: Vec<String> = Vec::new();
    let mut out_dir = "target/report".to_string();
    let mut save_dir: Option<String> = None;
    let mut only: Option<Vec<String>> = None;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--quick" => {
                scale = 0.15;
                reps = 9;
                mode = "quick";
            }
            "--long" => {
                scale = 4.0;
                reps = 61;
                mode = "long";
            }
            "--cases" => files.push(args.next().expect("--cases FILE")),
            "--out" => out_dir = args.next().expect("--out DIR"),
            "--save-cases" => save_dir = Some(args.next().expect("--save-cases DIR")),
            "--only" => {
                only = Some(args.next().expect("--only FAMILY[,FAMILY...]").split(',').map(String::from).collect())
            }
            "--reps" => match args.next().and_then(|n| n.parse().ok()).filter(|&n: &usize| n > 0) {
                Some(n) => reps = n,
                None => {
                    eprintln!("--reps takes a count of passes, at least 1");
                    std::process::exit(2);
                }
            },
            "-h" | "--help" => {
                println!("usage: report [--quick | --long] [--cases FILE]... [--out DIR] [--save-cases DIR] [--only FAMILY[,FAMILY...]] [--reps N]");
                return;
            }
            other => {
                eprintln!("unknown argument {other}; try --help");
                std::process::exit(2);
            }
        }
    }
    let start = Instant::now();
    let wanted = |name: &str| only.as_ref().is_none_or(|asked| asked.iter().any(|n| n == name));
    let mut names = Vec::new();
    let mut families = generate(scale, &mut |name| {
        names.push(name.to_string());
        wanted(name)
    });
    for f in &files {
        match load_cases(f) {
            Ok(fam) => {
                names.push(fam.name.clone());
                families.push(fam)
            }
            Err(e) => {
                eprintln!("[report] {e}");
                std::process::exit(1);
            }
        }
    }
    if let Some(asked) = &only {
        let unknown: Vec<&str> = asked.iter().filter(|n| !names.contains(n)).map(String::as_str).collect();
        if !unknown.is_empty() {
            eprintln!("[report] --only: no family {}; the families are {}", unknown.join(", "), names.join(", "));
            std::process::exit(2);
        }
        families.retain(|f| wanted(&f.name));
    }
    let mut rows = Vec::new();
    for f in &families {
        let t = Instant::now();
        // Each family in the least capacity that holds it, as a scene would
        // declare its polygons: spare slots are memory a pass reads past.
        match max_vertices(f) {
            0..=8 => run_family::<8>(f, reps, &mut rows),
            9..=16 => run_family::<16>(f, reps, &mut rows),
            17..=64 => run_family::<64>(f, reps, &mut rows),
            _ => run_family::<1100>(f, reps, &mut rows),
        }
        eprintln!("[report] measured {:<16} in {:5.2} s", f.name, t.elapsed().as_secs_f64());
    }
    // A partial run prints its rows and targets only: it writes no report
    // that could stand in for the whole one.
    if only.is_some() {
        println!("{}", plain_table(&HEADER, &table_rows(&rows)));
        println!("{}", targets(&rows, &|name| families.iter().any(|f| f.name == name)));
        return;
    }
    let t = Instant::now();
    let warm = warm::warm_table(&warm::warm_rows(reps));
    eprintln!("[report] measured warm starting in {:5.2} s", t.elapsed().as_secs_f64());
    let sweep_pts = sweep(&families, &rows, reps.min(5));

    let table = table_rows(&rows);
    let (sh, st) = stability(&rows);
    let tg = targets(&rows, &|_| true);
    let notes = "Errors are relative to L, the larger bounding radius of the pair; for rays L = max(bounding radius, distance from the ray origin to the shape's center); for casts (B moving by m against A) L is the pair's plus |m|, and the exact answer is the ray from the origin along m against the exact Minkowski difference A - B. \
A manifold (speculative margin 0) is wrong where it has points and the exact shapes are apart, or none and they overlap; its error is the larger of the farthest a point lies off its shape's boundary (each point on A and on B, exact distances) and the least separation's distance from the exact signed distance. \
A verdict is wrong only where the exact margin exceeds 8 eps L (eps of the precision). \
Value errors are taken where the query and the exact answer agree on the verdict; normal errors where the exact normal is unique. \
Exact answers: gjk2d-oracle (rational arithmetic), except ellipse_circle (Eberly's point-to-ellipse distance, bisected to the last f64 bit). \
parry2d 0.31 / parry2d-f64 0.31 through their public dyn-Shape API: intersection_test, distance (normal from closest_points), contact with prediction 0 for penetration, cast_ray_and_get_normal (solid) for rays, cast_shapes (A still, B moving by m, max time of impact 1; a penetration at the start counts as gjk2d's Start) for casts, DefaultQueryDispatcher's contact_manifolds (prediction 0, computed cold, points of separation at most 0) for manifolds; polygons built with from_convex_polyline_unmodified. \
parry has no ellipse. mean iters: GJK (+EPA) or ray-cast iterations reported by gjk2d, averaged over the queries that returned a result (0 for closed-form rays). iter-limit: results with Status::IterationLimit (\"+N capacity\": EPA's polytope filled, Status::CapacityLimit). ns/query: median over passes, each pass asking 16,384 distinct cases of the family once (its judged cases and more of the same kind, so the branch predictor cannot learn them; files: their own cases), gjk2d f32/f64 and parry f32/f64 passes interleaved in rotating order, single thread; parry/ours time and the targets' ratios: the median of the per-pass ratios of the two, taken side by side.";
    println!("\ngjk2d error against run time ({mode} run, {}, {})\n", today(), machine());
    println!("{}", plain_table(&HEADER, &table));
    println!("Stiff families (all queries together):\n");
    println!("{}", plain_table(&sh, &st));
    println!("Targets (our time / parry's, predictor-cold, same run; all at the accuracy in the table above):\n");
    println!("{tg}");
    println!("{notes}\n");
    println!("Warm starting (16,384 pairs of 8-gons, B moved by at most 1% of its size and turned by at most 1 degree a step):\n");
    println!("{warm}");

    let dir = std::path::Path::new(&out_dir);
    if let Err(e) = std::fs::create_dir_all(dir) {
        eprintln!("[report] cannot create {out_dir}: {e}");
        std::process::exit(1);
    }
    let md = format!(
        "# gjk2d: error against run time\n\n{mode} run of `cargo run --release --example report`, {}, on {}.\n\n{}\n## Stiff families\n\n{}\n## Targets\n\n{}\n{}\n\n## Warm starting\n\n{WARM_NOTE}\n\n{}\nThe sweep (error against time as settings vary) is in `sweep.csv` and `sweep.svg`.\n",
        today(),
        machine(),
        md_table(&HEADER, &table),
        md_table(&sh, &st),
        tg,
        notes,
        warm
    );
    let written = std::fs::write(dir.join("report.md"), md)
        .map_err(|e| e.to_string())
        .and_then(|_| write_sweep(dir, &sweep_pts).map_err(|e| e.to_string()));
    match written {
        Ok(()) => eprintln!(
            "[report] wrote {out_dir}/report.md, sweep.csv, sweep.svg in {:.1} s total",
            start.elapsed().as_secs_f64()
        ),
        Err(e) => {
            eprintln!("[report] writing {out_dir}: {e}");
            std::process::exit(1);
        }
    }
    if let Some(save) = save_dir {
        if let Err(e) = save_cases(std::path::Path::new(&save), &families) {
            eprintln!("[report] saving cases to {save}: {e}");
            std::process::exit(1);
        }
        eprintln!("[report] saved the generated cases to {save}/ (format: docs/speed.md)");
    }
}
