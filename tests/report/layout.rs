//! The HTML report on a narrow window, in headless Chromium: an 800 px laptop or tablet window
//! never scrolls sideways (what is wider scrolls inside its own box), and no table is wider
//! than its box there, so none is cut at the box's edge.

use super::{built, out_dir};
use std::process::Command;

/// Marks the page's measure for `--dump-dom`: the document's scroll and client widths, written
/// into an attribute of the body once the page has loaded.
const MEASURE: &str =
    "<script>addEventListener('load', () => { const d = document.documentElement; \
     document.body.setAttribute('data-widths', d.scrollWidth + ' ' + d.clientWidth); });</script>";

/// Marks, for `--dump-dom`, every table wider than its box (its scrolling wrapper, or itself
/// for a finding's table of numbers): the box's id or the table's index, and both widths.
const TABLES: &str = "<script>addEventListener('load', () => { const over = []; \
     document.querySelectorAll('table').forEach((t, i) => { \
     const b = t.classList.contains('numbers') ? t : t.parentElement; \
     const f = t.closest('figure'); \
     if (b.scrollWidth > b.clientWidth) over.push((f ? f.id : 'table ' + i) + ' ' + \
     b.scrollWidth + '/' + b.clientWidth); }); \
     document.body.setAttribute('data-widths', over.join('; ') || 'none'); });</script>";

/// (scroll width, client width) of `html` in a window `width` CSS pixels wide.
fn widths(html: &str, width: u32) -> (u32, u32) {
    let measured = measure(html, width, MEASURE);
    let mut n = measured.split(' ').map(|x| x.parse::<u32>().unwrap());
    (n.next().unwrap(), n.next().unwrap())
}

/// What `script` writes into the body's `data-widths` once `html` has loaded in a window
/// `width` CSS pixels wide.
fn measure(html: &str, width: u32, script: &str) -> String {
    let dir = out_dir(&format!("layout-{width}-{}", script.len()));
    let page = dir.join("report.html");
    std::fs::write(
        &page,
        html.replacen("</body>", &format!("{script}</body>"), 1),
    )
    .unwrap();
    let out = Command::new("chromium")
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--force-device-scale-factor=1",
            "--virtual-time-budget=10000",
            "--dump-dom",
        ])
        .arg(format!("--window-size={width},3000"))
        .arg(format!("--user-data-dir={}", dir.join("profile").display()))
        .arg(format!("file://{}", page.display()))
        .output()
        .expect("chromium runs");
    let dom = String::from_utf8_lossy(&out.stdout);
    dom.split_once("data-widths=\"")
        .and_then(|(_, rest)| rest.split_once('"'))
        .map(|(w, _)| w.to_string())
        .unwrap_or_else(|| {
            panic!(
                "chromium measured nothing; it said:\n{}",
                String::from_utf8_lossy(&out.stderr)
            )
        })
}

#[test]
#[ignore = "needs chromium (installed by .ci/run)"]
fn an_800_px_window_does_not_scroll_sideways() {
    let (scroll, client) = widths(&built().0, 800);
    assert!(
        client > 700 && client <= 800,
        "the window is not 800 px wide: client width {client}"
    );
    assert!(
        scroll <= client,
        "at 800 px the page scrolls sideways: {scroll} px of content in {client} px"
    );
}

#[test]
#[ignore = "needs chromium (installed by .ci/run)"]
fn at_800_px_every_table_fits_its_box() {
    let over = measure(&built().0, 800, TABLES);
    assert_eq!(over, "none", "tables wider than their box at 800 px");
}
