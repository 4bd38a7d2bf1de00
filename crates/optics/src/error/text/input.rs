//! An input refused before any law runs, in both languages side by side:
//! a vector or an angle that does not parse, the incidence given twice or
//! not at all, light a law has no answer for, a result past `f64`.

use record::{say, Lang};

/// A vector argument that is not three comma-separated parts.
pub(super) fn vector_parts(count: usize, lang: Lang) -> String {
    say!(
        lang,
        "expected three comma-separated numbers such as 0,3,4, got {count} part(s)",
        "három vesszővel elválasztott számot kell megadni (például 0,3,4), kapott részek száma: {count}"
    )
}

/// A component of a vector argument that is not a number.
pub(super) fn vector_component(axis: &str, text: &str, lang: Lang) -> String {
    say!(
        lang,
        "the {axis} component {text:?} is not a number",
        "a(z) {axis} komponens ({text:?}) nem szám"
    )
}

/// An angle in degrees outside `[0, 180]`.
pub(super) fn angle_degrees(name: &str, value: f64, lang: Lang) -> String {
    say!(
        lang,
        "{name} must be an angle in [0, 180] degrees, got {value}",
        "{name}: a [0, 180] fok tartományba eső szögnek kell lennie, kapott érték: {value}"
    )
}

/// Neither or both of the two ways of giving the incidence.
pub(super) fn cosine_or_angle(cosine: &str, angle: &str, lang: Lang) -> String {
    say!(
        lang,
        "give exactly one of {cosine} and {angle}",
        "{cosine} és {angle} közül pontosan egyet kell megadni"
    )
}

/// A material given twice or not at all.
pub(super) fn index_or_metal([eta, kappa, metal]: [&str; 3], lang: Lang) -> String {
    say!(
        lang,
        "give the material once: {eta} (with {kappa} for a conductor), or {metal} by name",
        "az anyagot egyszer kell megadni: {eta} (vezetőnél {kappa} is), vagy {metal} néven"
    )
}

/// A list given with nothing in it.
pub(super) fn empty_list(name: &str, lang: Lang) -> String {
    say!(
        lang,
        "{name} is empty: give at least one value",
        "{name} üres: legalább egy értéket kell megadni"
    )
}

/// Light from inside a conductor, in the quantity it was given as: an
/// angle in degrees, or a signed cosine.
pub(super) fn conductor_from_inside(
    name: &str,
    cos_i: f64,
    degrees: Option<f64>,
    lang: Lang,
) -> String {
    match degrees {
        Some(degrees) => say!(
            lang,
            "{name} must be at most 90 degrees for a conductor (kappa > 0): light cannot arrive from inside a metal, got {degrees}",
            "{name}: vezetőnél (kappa > 0) legfeljebb 90 fok lehet: fény nem érkezhet fém belsejéből, kapott érték: {degrees}"
        ),
        None => say!(
            lang,
            "{name} must be ≥ 0 for a conductor (kappa > 0): light cannot arrive from inside a metal, got {cos_i}",
            "{name}: vezetőnél (kappa > 0) ≥ 0 kell legyen: fény nem érkezhet fém belsejéből, kapott érték: {cos_i}"
        ),
    }
}

/// A critical angle asked for light going into a denser (or equal)
/// medium: each index's name and value.
pub(super) fn no_critical_angle(
    (name, n): (&str, f64),
    (name_outside, n_outside): (&str, f64),
    lang: Lang,
) -> String {
    say!(
        lang,
        "{name} = {n} is not larger than {name_outside} = {n_outside}: light going into a denser (or equal) medium always refracts, there is no critical angle",
        "{name} = {n} nem nagyobb, mint {name_outside} = {n_outside}: sűrűbb (vagy azonos) közegbe lépő fény mindig megtörik, nincs határszög"
    )
}

/// A result too large for `f64` from inputs that each are finite.
pub(super) fn overflow(quantity: &str, inputs: &[String], lang: Lang) -> String {
    say!(
        lang,
        "{quantity} overflows: it grows with {} past the largest finite number (1.8e308); give smaller values",
        "{quantity} túlcsordul: {} értékével a legnagyobb véges szám (1.8e308) fölé nő; kisebb értékeket kell megadni",
        inputs.join(", ")
    )
}
