//! The renders compared: ours flipping to Mitsuba's, the triptych, its scales.

use std::fmt::Write as _;

use radiometry::colour::srgb_encode;

use super::figure;
use super::format::escape;
use crate::compare::map::{heat_colour, LEGEND};
use crate::renders::TRIPTYCH_GAP;
use crate::report::Report;

/// Each render compared: ours, flipping to Mitsuba's under the pointer or
/// the keyboard's focus (the triptych's first two panels, so the two are
/// pixel for pixel the same size), and the whole triptych with the
/// difference map, its scale beside it.
pub(super) fn render_gallery(h: &mut String, report: &Report, figures: &[&String]) {
    if figures.is_empty() {
        return;
    }
    let _ = writeln!(
        h,
        "<h3 id=render-figures>Each render: ours, flipping to Mitsuba's</h3>\n\
         <p>Point at (or tab to) an image to see Mitsuba's render in its place; beside it \
         ours | Mitsuba | the difference, enlarged without smoothing. {}</p>\n<div class=figures>",
        heat_legend()
    );
    for file in figures {
        let name = file.rsplit('/').next().unwrap_or(file);
        let Some(f) = report.render_figures.iter().find(|f| f.file == name) else {
            figure(h, file);
            continue;
        };
        // Three panels and two gaps across, one panel high.
        let panel = (f.image.width - 2 * TRIPTYCH_GAP) / 3;
        let _ = writeln!(
            h,
            "<figure class=render><div class=flip tabindex=0 style=\"aspect-ratio:{panel}/{height}\">\
             <img class=pixels src=\"{src}\" alt=\"ours, or Mitsuba's under the pointer: {name}\"></div>\
             <figcaption>{label}: ours (pointed at: Mitsuba)</figcaption></figure>",
            height = f.image.height,
            src = escape(file),
            name = escape(name),
            label = escape(name.trim_start_matches("render_").trim_end_matches(".png")),
        );
        figure(h, file);
    }
    h.push_str("</div>\n");
}

/// The difference map's colour scale, drawn from the map's own colours.
fn heat_legend() -> String {
    let css = |c: glam::Vec3| {
        let [r, g, b] = [c.x, c.y, c.z].map(|v| (srgb_encode(f64::from(v)) * 255.0).round() as u8);
        format!("rgb({r},{g},{b})")
    };
    let stops: Vec<String> = (0..=8)
        .map(|k| {
            let t = f64::from(k) / 8.0;
            format!("{} {}%", css(heat_colour(&[t])), k * 100 / 8)
        })
        .collect();
    format!(
        "<span class=legend><span class=ramp style=\"background:linear-gradient(to right,{})\"></span> \
         0 to 1 <span class=swatch style=\"background:{}\"></span> beyond 1 \
         <span class=swatch style=\"background:{}\"></span> masked</span> (the difference map: {})",
        stops.join(","),
        css(heat_colour(&[2.0])),
        css(heat_colour(&[f64::NAN])),
        escape(LEGEND)
    )
}
