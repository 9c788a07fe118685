//! Case files (the format is in docs/speed.md): shapes parsed, answers recomputed by
//! the oracle (which also gives margins and normals) and checked against the file's;
//! and the generated families written as case files.

use crate::cases::{solve_pairs, solve_rays, Cases, Extra, Family, RayVerdict, Sh};
use std::fmt::Write as _;

fn parse_shape(t: &[&str], i: &mut usize) -> Result<Sh, String> {
    let f = |s: &str| s.parse::<f64>().map_err(|e| format!("{s}: {e}"));
    let kind = t.get(*i).ok_or("missing shape")?;
    *i += 1;
    let take = |i: &mut usize, k: usize| -> Result<Vec<f64>, String> {
        let v =
            t.get(*i..*i + k).ok_or("truncated shape")?.iter().map(|s| f(s)).collect::<Result<Vec<f64>, String>>()?;
        *i += k;
        Ok(v)
    };
    match *kind {
        "poly" => {
            let n: usize = t.get(*i).ok_or("missing count")?.parse().map_err(|e| format!("{e}"))?;
            *i += 1;
            let v = take(i, 2 * n)?;
            Ok(Sh::Poly(v.chunks(2).map(|c| [c[0], c[1]]).collect()))
        }
        "circle" => {
            let v = take(i, 3)?;
            Ok(Sh::Circle([v[0], v[1]], v[2]))
        }
        "capsule" => {
            let v = take(i, 5)?;
            Ok(Sh::Capsule([v[0], v[1]], [v[2], v[3]], v[4]))
        }
        k => Err(format!("unknown shape {k}")),
    }
}

pub(crate) fn load_cases(path: &str) -> Result<Family, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let mut pairs = Vec::new();
    let mut rays = Vec::new();
    let mut mismatches = 0;
    for (ln, line) in text.lines().enumerate() {
        let t: Vec<&str> = line.split_whitespace().collect();
        if t.is_empty() || t[0].starts_with('#') {
            continue;
        }
        let err = |e: String| format!("{path}:{}: {e}", ln + 1);
        let f = |s: &str| s.parse::<f64>().map_err(|e| err(format!("{s}: {e}")));
        if t[0] == "ray" {
            let mut i = 6;
            let s = parse_shape(&t, &mut i).map_err(err)?;
            let (o, d, m) = ([f(t[1])?, f(t[2])?], [f(t[3])?, f(t[4])?], f(t[5])?);
            if let (Some(st), Some(tt)) = (t.get(i), t.get(i + 1)) {
                rays.push((o, d, m, s, st.to_string(), f(tt)?));
            }
        } else {
            let mut i = 0;
            let a = parse_shape(&t, &mut i).map_err(err)?;
            let b = parse_shape(&t, &mut i).map_err(err)?;
            let (d, p) = (
                f(t.get(i).ok_or_else(|| err("no distance".into()))?)?,
                f(t.get(i + 1).ok_or_else(|| err("no depth".into()))?)?,
            );
            pairs.push((a, b, d, p));
        }
    }
    let name = std::path::Path::new(path).file_stem().map_or("cases".into(), |s| s.to_string_lossy().into_owned());
    let cases = if !rays.is_empty() {
        let given: Vec<(String, f64)> = rays.iter().map(|r| (r.4.clone(), r.5)).collect();
        let cases = solve_rays(rays.into_iter().map(|r| (r.0, r.1, r.2, r.3)).collect());
        for (c, (st, t)) in cases.iter().zip(&given) {
            let v = format!("{:?}", c.truth.verdict).to_lowercase();
            if &v != st || (c.truth.verdict == RayVerdict::Hit && (c.truth.t - t).abs() > 1e-12 * c.l) {
                mismatches += 1;
            }
        }
        Cases::Rays(cases)
    } else {
        let given: Vec<(f64, f64)> = pairs.iter().map(|p| (p.2, p.3)).collect();
        let cases = solve_pairs(pairs.into_iter().map(|p| (p.0, p.1)).collect());
        for (c, (d, p)) in cases.iter().zip(&given) {
            if (c.truth.distance - d).abs() > 1e-12 * c.l || (c.truth.depth - p).abs() > 1e-12 * c.l {
                mismatches += 1;
            }
        }
        Cases::Pairs(cases)
    };
    eprintln!(
        "[report] {path}: answers recomputed by the oracle; {mismatches} differ from the file's by more than 1e-12 L"
    );
    // A file's cases are timed as they are: no more of them to add.
    let extra = match cases {
        Cases::Pairs(_) => Extra::Pairs(Vec::new()),
        Cases::Rays(_) => Extra::Rays(Vec::new()),
        Cases::Casts(_) => Extra::Casts(Vec::new()),
    };
    Ok(Family { name: format!("file:{name}"), stiff: false, cases, extra })
}

/// Writes every generated family (ellipses excepted: the format has none) as a case
/// file (docs/speed.md has the format), for tests and for reproducing a row of the table.
pub(crate) fn save_cases(dir: &std::path::Path, families: &[Family]) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    for f in families.iter().filter(|f| !f.name.starts_with("file:")) {
        let mut s = String::new();
        match &f.cases {
            Cases::Pairs(c) => {
                for c in c {
                    if matches!(c.a, Sh::Ellipse(..)) {
                        continue;
                    }
                    let mut t = Vec::new();
                    c.a.tokens(&mut t);
                    c.b.tokens(&mut t);
                    let _ = writeln!(s, "{} {:?} {:?}", t.join(" "), c.truth.distance, c.truth.depth);
                }
            }
            Cases::Rays(c) => {
                for c in c {
                    let mut t = Vec::new();
                    c.s.tokens(&mut t);
                    let (st, tt, n) = match c.truth.verdict {
                        RayVerdict::Hit => ("hit", c.truth.t, c.truth.normal),
                        RayVerdict::Miss => ("miss", 0.0, [0.0; 2]),
                        RayVerdict::Inside => ("inside", 0.0, [0.0; 2]),
                    };
                    let _ = writeln!(
                        s,
                        "ray {:?} {:?} {:?} {:?} {:?} {} {st} {tt:?} {:?} {:?}",
                        c.o[0],
                        c.o[1],
                        c.d[0],
                        c.d[1],
                        c.max_len,
                        t.join(" "),
                        n[0],
                        n[1]
                    );
                }
            }
            // The case format has no casts: their cases are the generator's alone.
            Cases::Casts(_) => {}
        }
        if !s.is_empty() {
            std::fs::write(dir.join(format!("{}.txt", f.name)), s)?;
        }
    }
    Ok(())
}
