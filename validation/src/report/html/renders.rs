//! The renders compared: ours flipping to Mitsuba's, the triptych, its scales.

use std::fmt::Write as _;

use radiometry::colour::srgb_encode;

use super::figures::figure;
use super::format::escape;
use crate::compare::map::{heat_colour, LEGEND, LEGEND_HU};
use crate::flip;
use crate::renders::TRIPTYCH_GAP;
use crate::report::document::Report;
use record::{say, Lang};

/// Each render compared: ours, flipping to Mitsuba's under the pointer or
/// the keyboard's focus (the figure's first two panels, so the two are
/// pixel for pixel the same size), and the whole figure (ours | Mitsuba |
/// ꟻLIP | the difference | the mask), the scales beside them.
pub(super) fn render_gallery(h: &mut String, report: &Report, figures: &[&String], lang: Lang) {
    if figures.is_empty() {
        return;
    }
    let _ = writeln!(
        h,
        "{}",
        say!(
            lang,
            "<h3 id=render-figures>Each render: ours, flipping to Mitsuba's</h3>\n\
             <p>Point at (or tab to) an image to see Mitsuba's render in its place. Beside it, \
             enlarged without smoothing: ours | Mitsuba | ꟻLIP of ours against Mitsuba's | the \
             difference in units of what the test allows | where a check masks pixels, the mask.</p>\n\
             <p class=small>{}<br>{}<br>The mask: white where a pixel is not compared (an edge pixel, \
             whose colour depends on where each renderer's float32 ray meets the edge).</p>\n<div class=figures>",
            "<h3 id=render-figures>Minden kép: a miénk, ráállva a Mitsubáé</h3>\n\
             <p>Álljon egy képre az egérrel (vagy a Tab billentyűvel), és a helyén a Mitsuba képe \
             látszik. Mellette, simítás nélkül nagyítva: a miénk | a Mitsubáé | a miénk ꟻLIP-je a \
             Mitsubáéhoz képest | az eltérés a teszt által megengedett egységében | ahol az \
             ellenőrzés képpontokat maszkol, a maszk.</p>\n\
             <p class=small>{}<br>{}<br>A maszk: fehér, ahol a képpontot nem hasonlítjuk össze \
             (élen fekvő képpont, amelynek színe azon múlik, hol éri el az élt a két \
             sugárkövető float32 sugara).</p>\n<div class=figures>",
            flip_legend(lang),
            heat_legend(lang)
        )
    );
    for file in figures {
        let name = file.rsplit('/').next().unwrap_or(file);
        let Some(f) = report.render_figures.iter().find(|f| f.file == name) else {
            figure(h, file);
            continue;
        };
        // `panels` panels and the gaps between them across, one panel high;
        // Mitsuba's panel is the second, a `1 / (panels − 1)` of the way.
        let panel = (f.image.width - (f.panels - 1) * TRIPTYCH_GAP) / f.panels;
        let second = 100.0 / f64::from(f.panels.max(2) - 1);
        let (alt, caption) = match lang {
            Lang::En => (
                "ours, or Mitsuba's under the pointer",
                "ours (pointed at: Mitsuba)",
            ),
            Lang::Hu => (
                "a miénk, ráállva a Mitsubáé",
                "a miénk (ráállva: a Mitsubáé)",
            ),
        };
        let _ = writeln!(
            h,
            "<figure class=render><div class=flip tabindex=0 style=\"aspect-ratio:{panel}/{height};--second:{second:.4}%\">\
             <img class=pixels src=\"{src}\" alt=\"{alt}: {name}\"></div>\
             <figcaption>{label}: {caption}</figcaption></figure>",
            height = f.image.height,
            src = escape(file),
            name = escape(name),
            label = escape(name.trim_start_matches("render_").trim_end_matches(".png")),
        );
        figure(h, file);
    }
    h.push_str("</div>\n");
}

/// A linear colour as CSS.
fn css(c: glam::Vec3) -> String {
    let [r, g, b] = [c.x, c.y, c.z].map(|v| (srgb_encode(f64::from(v)) * 255.0).round() as u8);
    format!("rgb({r},{g},{b})")
}

/// A ramp of `colour` over [0, 1] in nine stops.
fn ramp(colour: impl Fn(f64) -> glam::Vec3) -> String {
    let stops: Vec<String> = (0..=8)
        .map(|k| format!("{} {}%", css(colour(f64::from(k) / 8.0)), k * 100 / 8))
        .collect();
    format!(
        "<span class=ramp style=\"background:linear-gradient(to right,{})\"></span>",
        stops.join(",")
    )
}

/// ꟻLIP's scale, drawn from the figure's own colours.
fn flip_legend(lang: Lang) -> String {
    say!(
        lang,
        "ꟻLIP: {} 0 (alike) to 1 (as different as two images can look), LDR ꟻLIP at {} \
         pixels per degree, Mitsuba's render as the reference.",
        "ꟻLIP: {} 0 (egyforma) és 1 (amennyire két kép csak különbözhet) között, LDR ꟻLIP \
         fokonként {} képponttal, a Mitsuba képe a viszonyítási alap.",
        ramp(|t| flip::magma(t as f32)),
        flip::PIXELS_PER_DEGREE
    )
}

/// The difference map's colour scale, drawn from the map's own colours.
fn heat_legend(lang: Lang) -> String {
    say!(
        lang,
        "The difference: {} 0 to 1 <span class=swatch style=\"background:{}\"></span> beyond 1 \
         <span class=swatch style=\"background:{}\"></span> masked ({}).",
        "Az eltérés: {} 0-tól 1-ig <span class=swatch style=\"background:{}\"></span> 1 fölött \
         <span class=swatch style=\"background:{}\"></span> maszkolt ({}).",
        ramp(|t| heat_colour(&[t])),
        css(heat_colour(&[2.0])),
        css(heat_colour(&[f64::NAN])),
        escape(lang.pick(LEGEND, LEGEND_HU))
    )
}
