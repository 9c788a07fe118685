//! Error against run time as gjk2d's settings vary, written as sweep.csv and
//! plotted as sweep.svg.

use crate::cases::{Cases, Family};
use crate::judge::Query;
use crate::ours::{build_family, measure_g};
use crate::run::Row;
use gjk2d::{EpaConfig, Gjk, GjkConfig, Real};
use std::fmt::Write as _;

pub(crate) struct SweepPoint {
    line: String,
    family: String,
    query: Query,
    prec: &'static str,
    imp: &'static str,
    setting: String,
    ns: f64,
    max_err: f64,
    med_err: f64,
    wrong: usize,
    limit: usize,
}

fn sweep_family<R: Real, const N: usize>(f: &Family, prec: &'static str, reps: usize, out: &mut Vec<SweepPoint>) {
    let gf = build_family::<R, N>(f);
    let mut point = |line: String, q: Query, setting: String, gjk: &Gjk<R>| {
        let m = measure_g(f, &gf, gjk, q, reps);
        out.push(SweepPoint {
            line,
            family: f.name.clone(),
            query: q,
            prec,
            imp: "gjk2d",
            setting,
            ns: m.ns,
            max_err: m.acc.max_err(),
            med_err: m.acc.med_err(),
            wrong: m.acc.wrong,
            limit: m.acc.limit + m.acc.capacity,
        });
    };
    let epsilons = [1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12];
    let limits = [5u32, 8, 12, 16, 24, 32, 64];
    let name = &f.name;
    match (name.as_str(), &f.cases) {
        // A cast has no setting the sweep varies that a ray's sweep does not show.
        (_, Cases::Casts(_)) => {}
        (_, Cases::Pairs(_)) => {
            for q in [Query::Distance, Query::Penetration] {
                for e in epsilons {
                    let mut gjk = Gjk::<R>::new();
                    if q == Query::Distance {
                        gjk.config.set_distance_epsilon(R::from_f64(e)).unwrap();
                    } else {
                        let mut epa = EpaConfig::default();
                        epa.set_epsilon(R::from_f64(e)).unwrap();
                        gjk.solver = gjk2d::Epa::new(epa);
                    }
                    let what = if q == Query::Distance { "distance eps" } else { "EPA eps" };
                    point(format!("{prec} {name} {} ({what} 1e-2..1e-12)", q.name()), q, format!("{what} {e:e}"), &gjk);
                }
                for n in limits {
                    let mut gjk = Gjk::<R>::new();
                    if q == Query::Distance {
                        gjk.config.set_max_distance_iterations(n).unwrap();
                    } else {
                        let mut epa = EpaConfig::default();
                        epa.set_max_iterations(n).unwrap();
                        gjk.solver = gjk2d::Epa::new(epa);
                    }
                    let what = if q == Query::Distance { "GJK iterations" } else { "EPA iterations" };
                    point(format!("{prec} {name} {} ({what} 5..64)", q.name()), q, format!("{what} {n}"), &gjk);
                }
            }
        }
        (_, Cases::Rays(_)) => {
            let mut closed = Gjk::<R>::new();
            closed.closed_form_rays = true;
            point(format!("{prec} {name} ray (closed form vs iterative)"), Query::Ray, "closed form".into(), &closed);
            for e in epsilons {
                let mut gjk = Gjk::<R>::new();
                gjk.closed_form_rays = false;
                gjk.config.set_raycast_epsilon(R::from_f64(e)).unwrap();
                point(
                    format!("{prec} {name} ray (iterative, raycast eps 1e-2..1e-12)"),
                    Query::Ray,
                    format!("raycast eps {e:e}"),
                    &gjk,
                );
            }
            let mut iter = Gjk::<R>::new();
            iter.closed_form_rays = false;
            point(
                format!("{prec} {name} ray (closed form vs iterative)"),
                Query::Ray,
                "iterative (default eps)".into(),
                &iter,
            );
        }
    }
    let _ = GjkConfig::<R>::default();
}

pub(crate) fn sweep(families: &[Family], rows: &[Row], reps: usize) -> Vec<SweepPoint> {
    let mut pts = Vec::new();
    for f in
        families.iter().filter(|f| ["ellipse_circle", "poly64", "ray_circle", "ray_poly8"].contains(&f.name.as_str()))
    {
        eprintln!("[report] sweep: {}", f.name);
        sweep_family::<f32, 64>(f, "f32", reps, &mut pts);
        sweep_family::<f64, 64>(f, "f64", reps, &mut pts);
        for r in rows.iter().filter(|r| r.family == f.name) {
            if let Some(p) = &r.parry {
                if r.query == Query::Intersect {
                    continue;
                }
                pts.push(SweepPoint {
                    line: format!("parry {} {} {}", r.prec, r.family, r.query.name()),
                    family: r.family.clone(),
                    query: r.query,
                    prec: r.prec,
                    imp: "parry2d",
                    setting: "default".into(),
                    ns: p.ns,
                    max_err: p.acc.max_err(),
                    med_err: p.acc.med_err(),
                    wrong: p.acc.wrong,
                    limit: p.acc.limit + p.acc.capacity,
                });
            }
        }
    }
    pts
}

pub(crate) fn write_sweep(dir: &std::path::Path, pts: &[SweepPoint]) -> Result<(), Box<dyn std::error::Error>> {
    let mut csv = String::from("line,family,query,precision,impl,setting,ns_per_query,max_err_rel_L,median_err_rel_L,wrong_verdicts,limit_hits_iteration_or_capacity\n");
    for p in pts {
        writeln!(
            csv,
            "\"{}\",{},{},{},{},{},{:.2},{:e},{:e},{},{}",
            p.line,
            p.family,
            p.query.name(),
            p.prec,
            p.imp,
            p.setting,
            p.ns,
            p.max_err,
            p.med_err,
            p.wrong,
            p.limit
        )?;
    }
    std::fs::write(dir.join("sweep.csv"), csv)?;

    use plotters::prelude::*;
    // One panel per (family, query): a line per setting family and precision, a
    // triangle per peer (parry2d, parry2d-f64) at its defaults.
    let floor = 1e-17;
    let y = |e: f64| e.max(floor);
    let mut panels: Vec<(String, Query)> = Vec::new();
    for p in pts {
        if !panels.contains(&(p.family.clone(), p.query)) {
            panels.push((p.family.clone(), p.query));
        }
    }
    let path = dir.join("sweep.svg");
    let cols = 2usize;
    let rows_n = panels.len().div_ceil(cols).max(1);
    let root = SVGBackend::new(&path, (1400, 520 * rows_n as u32)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(
        "gjk2d: max error / L against ns per query, log-log (an error of 0 is drawn at 1e-17)",
        ("sans-serif", 22),
    )?;
    let areas = root.split_evenly((rows_n, cols));
    for ((family, query), area) in panels.iter().zip(areas.iter()) {
        let mine: Vec<&SweepPoint> = pts.iter().filter(|p| &p.family == family && p.query == *query).collect();
        let (mut xmin, mut xmax, mut ymin) = (f64::MAX, 0f64, 1f64);
        for p in &mine {
            xmin = xmin.min(p.ns);
            xmax = xmax.max(p.ns);
            ymin = ymin.min(y(p.max_err));
        }
        let mut chart = ChartBuilder::on(area)
            .caption(format!("{family}: {}", query.name()), ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(65)
            .build_cartesian_2d((xmin * 0.8..xmax * 1.25).log_scale(), (ymin * 0.3..1.0).log_scale())?;
        chart
            .configure_mesh()
            .x_desc("ns per query")
            .y_desc("max error / L")
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .x_label_formatter(&|v| format!("{v:.0}"))
            .draw()?;
        let mut lines: Vec<&str> = Vec::new();
        for p in &mine {
            if !lines.contains(&p.line.as_str()) {
                lines.push(&p.line);
            }
        }
        for (i, line) in lines.iter().enumerate() {
            let color = Palette99::pick(i).to_rgba();
            let ps: Vec<(f64, f64)> = mine.iter().filter(|p| p.line == *line).map(|p| (p.ns, y(p.max_err))).collect();
            let label = line.replacen(&format!(" {family}"), "", 1);
            if line.starts_with("parry") {
                chart
                    .draw_series(PointSeries::of_element(ps, 8, color, &|c, s, st| {
                        TriangleMarker::new(c, s, st.filled())
                    }))?
                    .label(label)
                    .legend(move |(x, y)| TriangleMarker::new((x + 10, y), 5, color.filled()));
            } else {
                chart
                    .draw_series(LineSeries::new(ps.clone(), color.stroke_width(2)))?
                    .label(label)
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2)));
                chart.draw_series(PointSeries::of_element(ps, 3, color, &|c, s, st| Circle::new(c, s, st.filled())))?;
            }
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerLeft)
            .label_font(("sans-serif", 12))
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
    }
    root.present()?;
    Ok(())
}
