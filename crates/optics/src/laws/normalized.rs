//! The working's note that a direction given was not unit length, shared
//! by the laws that take directions.

use radiometry::domain::Direction;
use record::{number, vector, Record};
use record::{say, Lang};

/// Says in the working when a direction was not unit length.
pub fn note_normalized(record: &mut Record, lang: Lang, field: &str, d: &Direction) {
    if d.was_normalized() {
        record.step(|| {
            let noun = direction_hu(field);
            say!(
                lang,
                "{field} has length {}: normalised to {}",
                "{noun} hossza {}: normalizálva {}",
                number(d.given_length),
                vector(d.unit.to_array())
            )
        });
    }
}

/// A direction's name in a Hungarian sentence, the input's own name beside
/// it: `a fényirány (light_dir)`.
fn direction_hu(field: &str) -> String {
    let noun = match field {
        "normal" => "a felületi normális",
        "light_dir" => "a fényirány",
        "view_dir" => "a nézeti irány",
        "wi" => "a beeső irány",
        "dir" => "a visszavert irány",
        _ => "az irány",
    };
    format!("{noun} ({field})")
}
