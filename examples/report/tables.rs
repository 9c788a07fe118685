//! The report's tables: every row, the stiff families and the speed targets.

use crate::judge::{Acc, Query};
use crate::run::Row;
use std::fmt::Write as _;

fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if x.is_nan() {
        "-".into()
    } else {
        format!("{x:.1e}")
    }
}

pub(crate) const HEADER: [&str; 18] = [
    "family",
    "query",
    "prec",
    "cases",
    "wrong",
    "max err/L",
    "med err/L",
    "max normal (rad)",
    "ns/query",
    "mean iters",
    "iter-limit",
    "NaN/inf",
    "parry wrong",
    "parry max err/L",
    "parry med err/L",
    "parry normal (rad)",
    "parry ns/query",
    "parry/ours time",
];

pub(crate) fn table_rows(rows: &[Row]) -> Vec<Vec<String>> {
    rows.iter()
        .map(|r| {
            let o = &r.ours;
            let mut v = vec![
                r.family.clone(),
                r.query.name().to_string(),
                r.prec.to_string(),
                o.acc.cases.to_string(),
                o.acc.wrong.to_string(),
                sci(o.acc.max_err()),
                sci(o.acc.med_err()),
                sci(o.acc.max_nerr()),
                format!("{:.0}", o.ns),
                if o.acc.answered > 0 {
                    format!("{:.1}", o.acc.iters as f64 / o.acc.answered as f64)
                } else {
                    "-".into()
                },
                if o.acc.capacity > 0 {
                    format!("{} +{} capacity", o.acc.limit, o.acc.capacity)
                } else {
                    o.acc.limit.to_string()
                },
                o.acc.nonfinite.to_string(),
            ];
            match &r.parry {
                Some(p) => v.extend([
                    format!(
                        "{}{}",
                        p.acc.wrong,
                        if p.acc.nonfinite > 0 { format!(" ({} NaN)", p.acc.nonfinite) } else { String::new() }
                    ),
                    sci(p.acc.max_err()),
                    sci(p.acc.med_err()),
                    sci(p.acc.max_nerr()),
                    format!("{:.0}", p.ns),
                    format!("{:.2}", 1.0 / r.ratio.unwrap_or(f64::NAN)),
                ]),
                None => v.extend([
                    "n/a (no ellipse in parry)".into(),
                    "-".into(),
                    "-".into(),
                    "-".into(),
                    "-".into(),
                    "-".into(),
                ]),
            }
            v
        })
        .collect()
}

pub(crate) fn plain_table(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut w: Vec<usize> = header.iter().map(|h| h.len()).collect();
    for r in rows {
        for (i, c) in r.iter().enumerate() {
            w[i] = w[i].max(c.len());
        }
    }
    let mut s = String::new();
    let line = |s: &mut String, cells: Vec<&str>| {
        for (i, c) in cells.iter().enumerate() {
            let _ = write!(s, "{:>w$} ", c, w = w[i]);
        }
        s.push('\n');
    };
    line(&mut s, header.to_vec());
    for r in rows {
        line(&mut s, r.iter().map(|c| c.as_str()).collect());
    }
    s
}

pub(crate) fn md_table(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut s = format!("| {} |\n|{}\n", header.join(" | "), "---|".repeat(header.len()));
    for r in rows {
        let _ = writeln!(s, "| {} |", r.join(" | "));
    }
    s
}

/// The stiff families: everything that can go wrong, per family and precision, and the
/// bound on the value error that held (as a multiple of eps L).
pub(crate) fn stability(rows: &[Row]) -> (Vec<&'static str>, Vec<Vec<String>>) {
    let header = vec![
        "family",
        "prec",
        "cases",
        "wrong verdicts",
        "NaN/inf",
        "iter-limit",
        "worst err/L",
        "bound held",
        "parry wrong",
        "parry worst err/L",
        "parry bound",
    ];
    let mut out = Vec::new();
    let mut keys: Vec<(String, &str)> = Vec::new();
    for r in rows.iter().filter(|r| r.stiff) {
        if !keys.contains(&(r.family.clone(), r.prec)) {
            keys.push((r.family.clone(), r.prec));
        }
    }
    let bound = |worst: f64, eps: f64| {
        let m = worst / eps;
        if m <= 8.0 {
            "held: 8 eps L".to_string()
        } else {
            format!("{:.3} eps L", m)
        }
    };
    for (fam, prec) in keys {
        let rs: Vec<&Row> = rows.iter().filter(|r| r.family == fam && r.prec == prec).collect();
        let eps = rs[0].eps;
        let cases = rs[0].ours.acc.cases;
        let sum = |f: &dyn Fn(&Acc) -> usize| rs.iter().map(|r| f(&r.ours.acc)).sum::<usize>();
        let worst = rs.iter().map(|r| r.ours.acc.max_err()).fold(0.0, f64::max);
        let pw: usize = rs.iter().filter_map(|r| r.parry.as_ref()).map(|p| p.acc.wrong + p.acc.nonfinite).sum();
        let pworst = rs.iter().filter_map(|r| r.parry.as_ref()).map(|p| p.acc.max_err()).fold(0.0, f64::max);
        out.push(vec![
            fam,
            prec.to_string(),
            cases.to_string(),
            sum(&|a| a.wrong).to_string(),
            sum(&|a| a.nonfinite).to_string(),
            sum(&|a| a.limit + a.capacity).to_string(),
            sci(worst),
            bound(worst, eps),
            pw.to_string(),
            sci(pworst),
            bound(pworst, eps),
        ]);
    }
    (header, out)
}

/// Time ratios against the targets, as geometric means over families.
/// Issue 27's targets: our time / parry's, per family, query and precision, each
/// timed predictor-cold in the same run. Only the families `measured` names
/// get a line: a partial run has no figures for the others.
pub(crate) fn targets(rows: &[Row], measured: &dyn Fn(&str) -> bool) -> String {
    // (family, intersect, distance, penetration) goals; rays have one.
    const PAIR_GOALS: [(&str, f64, f64, f64); 6] = [
        ("poly8", 0.4, 0.5, 0.35),
        ("poly64", 0.3, 0.3, 0.3),
        ("poly1024", 0.1, 0.1, 0.1),
        ("circle_poly", 0.3, 0.3, 0.3),
        ("capsule_poly", 0.3, 0.3, 0.3),
        ("circle_circle", 1.0, 1.0, 1.0),
    ];
    const RAY_GOALS: [(&str, f64); 2] = [("ray_poly8", 0.25), ("ray_circle", 1.0)];
    let mut s = String::from("| family | query | goal | f32 | f64 | |\n|---|---|---:|---:|---:|---|\n");
    let mut line = |family: &str, q: Query, goal: f64| {
        let ratio = |prec: &str| {
            rows.iter()
                .find(|r| r.family == family && r.query == q && r.prec == prec)
                .and_then(|r| r.ratio)
                .unwrap_or(f64::NAN)
        };
        let (a, b) = (ratio("f32"), ratio("f64"));
        let met = a <= goal && b <= goal;
        let _ = writeln!(
            s,
            "| {family} | {} | <= {goal} | {a:.2} | {b:.2} | {} |",
            q.name(),
            if met { "met" } else { "MISSED" }
        );
    };
    for (family, i, d, p) in PAIR_GOALS.into_iter().filter(|goal| measured(goal.0)) {
        line(family, Query::Intersect, i);
        line(family, Query::Distance, d);
        line(family, Query::Penetration, p);
    }
    for (family, goal) in RAY_GOALS.into_iter().filter(|goal| measured(goal.0)) {
        line(family, Query::Ray, goal);
    }
    let slower: Vec<String> = rows
        .iter()
        .filter_map(|r| {
            let x = r.ratio?;
            (x > 1.0).then(|| format!("{} {} {} ({x:.2})", r.family, r.query.name(), r.prec))
        })
        .collect();
    let _ =
        writeln!(s, "\nSlower than parry: {}.", if slower.is_empty() { "none".to_string() } else { slower.join(", ") });
    s
}

pub(crate) fn today() -> String {
    let secs = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs()) as i64;
    // Howard Hinnant's civil_from_days.
    let z = secs.div_euclid(86_400) + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + (m <= 2) as i64;
    format!("{y:04}-{m:02}-{d:02}")
}

pub(crate) fn machine() -> String {
    let model = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let n = std::thread::available_parallelism().map_or(1, |n| n.get());
    format!("{model}, {n} core{}", if n == 1 { "" } else { "s" })
}
