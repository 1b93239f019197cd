//! Where the label of a reference line goes: just inside the plot at the top of a vertical line
//! (to one side of it) or at the left end of a horizontal one; moved down below the legend when
//! the legend would hide it, and below any label already placed (two lines close together); a
//! vertical line's label on the side where, so placed, it covers fewer plotted points and stays
//! inside the plot (on a tie, on the left of a line in the right part of the plot).
//!
//! Pure geometry in the plotting area's pixels ([`Rect`]'s frame), so that it is tested without
//! drawing; `canvas.rs` measures the label and counts the points.

use super::legend::Rect;

/// A label to place.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Label {
    /// Whether the line is vertical (a mark on the x axis).
    pub vertical: bool,
    /// The anchor: the top of a vertical line, the left end of a horizontal one.
    pub at: (i32, i32),
    /// The label's size.
    pub size: (i32, i32),
    /// Where the line is across the plot, 0 (left) to 1 (right).
    pub frac: f64,
    /// The plot's left and right edges.
    pub plot_x: (i32, i32),
    /// One px of the usual size in this drawing's pixels (the drawing's scale).
    pub unit: f64,
}

/// Where the label went: its offset from the anchor, whether it is on the left of the line,
/// and its box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Placed {
    /// Offset of the text's anchor point from the line's anchor.
    pub offset: (i32, i32),
    /// On the left of a vertical line (the text is then right-aligned to the offset).
    pub left: bool,
    /// The label's box.
    pub rect: Rect,
}

/// Places `label`, avoiding the legend box and the labels already `placed`; `covered` counts
/// the plotted points inside a box.
pub(crate) fn place(
    label: &Label,
    legend: Option<Rect>,
    placed: &[Rect],
    covered: &dyn Fn(&Rect) -> usize,
) -> Placed {
    let px = |v: f64| (v * label.unit).round() as i32;
    let (tw, th) = label.size;
    let on = |left: bool| -> Placed {
        let (dx, dy) = match (label.vertical, left) {
            (true, true) => (-px(4.0), px(4.0)),
            (true, false) => (px(4.0), px(4.0)),
            (false, _) => (px(6.0), -px(16.0)),
        };
        let lx = label.at.0 + dx - if left { tw } else { 0 };
        let boxed = |dy: i32| Rect {
            x0: lx,
            y0: label.at.1 + dy,
            x1: lx + tw,
            y1: label.at.1 + dy + th,
        };
        let overlaps =
            |a: &Rect, b: &Rect| a.x0 <= b.x1 && a.x1 >= b.x0 && a.y0 <= b.y1 && a.y1 >= b.y0;
        let mut dy = match legend {
            Some(r) if overlaps(&boxed(dy), &r) => dy + (r.y1 - boxed(dy).y0) + px(4.0),
            _ => dy,
        };
        while placed.iter().any(|p| overlaps(&boxed(dy), p)) {
            dy += th + px(2.0);
        }
        Placed {
            offset: (dx, dy),
            left,
            rect: boxed(dy),
        }
    };
    if !label.vertical {
        return on(false);
    }
    let score = |left: bool| {
        let p = on(left);
        (p.rect.x0 >= label.plot_x.0 && p.rect.x1 <= label.plot_x.1).then(|| covered(&p.rect))
    };
    let left = match (score(true), score(false)) {
        (Some(l), Some(r)) if l != r => l < r,
        (Some(_), None) => true,
        (None, Some(_)) => false,
        _ => label.frac > 0.6,
    };
    on(left)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn label(frac: f64) -> Label {
        Label {
            vertical: true,
            at: ((frac * 400.0) as i32, 0),
            size: (60, 12),
            frac,
            plot_x: (0, 400),
            unit: 1.0,
        }
    }

    #[test]
    fn a_label_goes_where_it_covers_fewer_points_and_stays_inside() {
        let none = |_: &Rect| 0;
        // On a tie, left of a line in the right part, right of one in the left part.
        assert!(place(&label(0.7), None, &[], &none).left);
        assert!(!place(&label(0.3), None, &[], &none).left);
        // Data on the left of the line (x < 280) sends the label right.
        let data_left = |r: &Rect| if r.x0 < 280 { 10 } else { 0 };
        assert!(!place(&label(0.7), None, &[], &data_left).left);
        // Unless it would leave the plot.
        assert!(place(&label(0.95), None, &[], &data_left).left);
    }

    #[test]
    fn a_label_moves_below_the_legend_and_below_labels_already_placed() {
        let none = |_: &Rect| 0;
        let legend = Rect {
            x0: 0,
            y0: 0,
            x1: 400,
            y1: 50,
        };
        let p = place(&label(0.3), Some(legend), &[], &none);
        assert!(p.rect.y0 > 50, "{p:?}");
        let q = place(&label(0.3), Some(legend), &[p.rect], &none);
        assert!(q.rect.y0 > p.rect.y1, "{q:?} under {p:?}");
    }
}
