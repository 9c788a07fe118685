//! The documentation pages against what they point at and quote: every
//! relative link in README.md and its detail pages resolves, and the speed
//! targets that docs/speed.md and README.md quote are the committed report's
//! (`report/report.md`). Refresh them together, from one run:
//! `cargo run --release --example report -- --out report`, then paste its
//! targets table into docs/speed.md and its count into README.md.
//! (firmware/run.sh checks the firmware figures the same way.)

use std::path::Path;

const PAGES: [&str; 6] =
    ["README.md", "docs/examples.md", "docs/accuracy.md", "docs/speed.md", "firmware/README.md", "web/README.md"];

fn read(path: &str) -> String {
    let full = Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("{}: {e}", full.display()))
}

/// The targets of markdown links and images (`](target)`) that are neither
/// URLs nor anchors on the same page, without their anchors.
fn relative_links(text: &str) -> Vec<&str> {
    text.match_indices("](")
        .filter_map(|(i, _)| {
            let rest = &text[i + 2..];
            let target = &rest[..rest.find(')')?];
            let file = target.split('#').next().unwrap_or_default();
            (!file.is_empty() && !target.contains("://")).then_some(file)
        })
        .collect()
}

#[test]
fn every_relative_link_resolves() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut broken = Vec::new();
    for page in PAGES {
        let dir = root.join(page).parent().expect("a page is in a directory").to_path_buf();
        for link in relative_links(&read(page)) {
            if !dir.join(link).exists() {
                broken.push(format!("{page}: {link}"));
            }
        }
    }
    assert!(broken.is_empty(), "links to nothing:\n{}", broken.join("\n"));
}

#[test]
fn speed_targets_are_the_committed_reports() {
    let report = read("report/report.md");
    let targets: Vec<&str> = report
        .split("\n## Targets\n")
        .nth(1)
        .expect("report/report.md has a Targets section")
        .split("\n## ")
        .next()
        .unwrap_or_default()
        .lines()
        .filter(|l| l.starts_with('|') || l.starts_with("Slower than parry: "))
        .collect();
    let speed = read("docs/speed.md");
    let missing: Vec<&str> = targets.iter().copied().filter(|t| !speed.lines().any(|l| l == *t)).collect();
    assert!(
        missing.is_empty(),
        "docs/speed.md lacks these lines of report/report.md's targets:\n{}",
        missing.join("\n")
    );

    // README's status row: how many targets are met, and which queries are
    // slower than parry's, in the report of that date.
    let date = report
        .lines()
        .find_map(|l| l.strip_prefix("default run of `cargo run --release --example report`, "))
        .and_then(|l| l.split(", ").next())
        .expect("report/report.md says the date of its default run");
    let met = targets.iter().filter(|t| t.ends_with("| met |")).count();
    let total = met + targets.iter().filter(|t| t.ends_with("| MISSED |")).count();
    let slower = targets
        .iter()
        .find_map(|t| t.strip_prefix("Slower than parry: "))
        .map(|s| s.trim_end_matches('.'))
        .expect("report/report.md says which queries are slower than parry's");
    let readme = read("README.md");
    let count = format!("{met} of {total} targets met in the report of {date}");
    for quote in [count, format!("Slower than parry: {slower}")] {
        assert!(readme.contains(&quote), "README.md should say: {quote}");
    }
    assert!(speed.contains(date), "docs/speed.md should date its targets {date}");
}
