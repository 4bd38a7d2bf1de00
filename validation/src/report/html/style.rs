//! The page's style sheet.

/// The style of `report.html`, one rule a line.
pub(super) const STYLE: &str = "body{font-family:sans-serif;max-width:72em;margin:1em auto;padding:0 1em;line-height:1.4;overflow-wrap:anywhere}\
h2{margin-top:2em;border-bottom:1px solid #ddd}\
.verdict{font-size:1.3em;font-weight:bold;margin-bottom:.2em}.small{font-size:.9em;color:#444}\
.cards{display:grid;grid-template-columns:repeat(auto-fill,minmax(12.5em,1fr));gap:.6em}\
.card{border:1px solid #ccc;border-radius:.4em;padding:.6em;min-width:0}\
.card h3{margin:0 0 .3em;font-size:1em}.card a{color:inherit}.card img{width:100%;height:6em;object-fit:contain}\
.scroll{overflow-x:auto;max-width:100%}\
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:.2em .5em;text-align:left;vertical-align:top}\
td{overflow-wrap:anywhere}td.num{text-align:right;font-family:monospace;white-space:nowrap}\
.pass{color:#070}.fail{color:#b00;font-weight:bold}\
.swatch{display:inline-block;width:2em;height:1em;border:1px solid #888;vertical-align:middle}\
details{margin:.5em 0}summary{cursor:pointer}\
.side{display:flex;flex-wrap:wrap;gap:1em;align-items:flex-start}.side>*{min-width:0;flex:1 1 24em}\
.figures{display:flex;flex-wrap:wrap;gap:1em}figure{margin:0;max-width:100%;min-width:0}\
img{max-width:100%}img.pixels{image-rendering:pixelated}\
figcaption{font-size:.85em;color:#444;overflow-wrap:anywhere}\
.render{width:16em;max-width:100%}.flip img{display:block;width:100%;height:100%;object-fit:cover;object-position:0 0}\
.flip:hover img,.flip:focus img{object-position:var(--second) 0}.flip:focus{outline:2px solid #36c}\
.trade td,.trade th{overflow-wrap:normal}.trade td:first-child{min-width:9em}.trade td:last-child{white-space:nowrap}.plot{max-width:48em}\
.ramp{display:inline-block;width:8em;height:1em;border:1px solid #888;vertical-align:middle}code{background:#f4f4f4;overflow-wrap:anywhere}";
