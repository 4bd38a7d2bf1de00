//! The working's note that a direction given was not unit length, shared
//! by the laws that take directions.

use radiometry::domain::Direction;
use record::{number, vector, Record};
use record::{say, Lang};

/// Says in the working when a direction was not unit length.
pub fn note_normalized(record: &mut Record, lang: Lang, field: &str, d: &Direction) {
    if d.was_normalized() {
        record.step(|| {
            say!(
                lang,
                "{field} has length {}: normalised to {}",
                "{field} hossza {}: normalizálva {}",
                number(d.given_length),
                vector(d.unit.to_array())
            )
        });
    }
}
