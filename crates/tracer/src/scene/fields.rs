//! The fields of the schema, each as a pattern of the JSON paths the
//! errors name (`docs/scene-schema.md` describes each): what a refusal may
//! name, and the longest known part of a path the text breaks off in.

/// Every field of the schema (`docs/scene-schema.md`): `[]` an index, `*`
/// a material's name.
pub const FIELDS: &[&str] = &[
    "version",
    "image",
    "image.width",
    "image.height",
    "camera",
    "camera.type",
    "camera.eye",
    "camera.eye[]",
    "camera.target",
    "camera.target[]",
    "camera.up",
    "camera.up[]",
    "camera.fov_y_deg",
    "camera.near",
    "camera.far",
    "background",
    "background[]",
    "environment",
    "environment.type",
    "environment.scale",
    "environment.image",
    "environment.faces",
    "environment.faces[]",
    "ambient",
    "ambient[]",
    "materials",
    "materials.*",
    "materials.*.type",
    "materials.*.radiance",
    "materials.*.radiance[]",
    "materials.*.ambient",
    "materials.*.ambient[]",
    "materials.*.diffuse",
    "materials.*.diffuse[]",
    "materials.*.specular",
    "materials.*.specular[]",
    "materials.*.shininess",
    "materials.*.albedo",
    "materials.*.albedo[]",
    "materials.*.n",
    "materials.*.n[]",
    "materials.*.kappa",
    "materials.*.kappa[]",
    "materials.*.eta",
    "objects",
    "objects[]",
    "objects[].type",
    "objects[].center",
    "objects[].center[]",
    "objects[].radius",
    "objects[].material",
    "objects[].point",
    "objects[].point[]",
    "objects[].normal",
    "objects[].normal[]",
    "objects[].axis_point",
    "objects[].axis_point[]",
    "objects[].axis",
    "objects[].axis[]",
    "objects[].sides",
    "objects[].bump",
    "objects[].bump.type",
    "objects[].bump.du",
    "objects[].bump.dv",
    "objects[].bump.amplitude",
    "objects[].bump.period",
    "lights",
    "lights[]",
    "lights[].type",
    "lights[].towards",
    "lights[].towards[]",
    "lights[].irradiance",
    "lights[].irradiance[]",
    "lights[].position",
    "lights[].position[]",
    "lights[].intensity",
    "lights[].intensity[]",
    "render",
    "render.integrator",
    "render.spp",
    "render.max_depth",
    "render.fresnel",
    "render.throughput_cutoff",
    "render.seed",
    "render.ray_offset",
    "render.ray_offset.fixed",
    "render.ray_offset.scaled",
    "render.pixel_filter",
    "render.photons",
    "render.photon_passes",
    "render.photon_radius",
    "render.precision",
];

/// Whether `path` matches `pattern`: `[]` an index `[digits]`, `*` one or
/// more characters (a material's name may hold dots and brackets).
fn matches(pattern: &str, path: &str) -> bool {
    if let Some(rest) = pattern.strip_prefix("[]") {
        let Some(after) = path.strip_prefix('[') else {
            return false;
        };
        let digits = after.chars().take_while(char::is_ascii_digit).count();
        return digits > 0
            && after[digits..].starts_with(']')
            && matches(rest, &after[digits + 1..]);
    }
    if let Some(rest) = pattern.strip_prefix('*') {
        return (1..=path.len())
            .filter(|&i| path.is_char_boundary(i))
            .any(|i| matches(rest, &path[i..]));
    }
    match (pattern.chars().next(), path.chars().next()) {
        (None, None) => true,
        (Some(a), Some(b)) if a == b => matches(&pattern[a.len_utf8()..], &path[b.len_utf8()..]),
        _ => false,
    }
}

/// The schema's field that `path` is, if any.
pub fn field_of(path: &str) -> Option<&'static str> {
    // The longest pattern that matches: `materials.*.eta` over `materials.*`.
    FIELDS
        .iter()
        .copied()
        .filter(|f| matches(f, path))
        .max_by_key(|f| f.len())
}

/// The longest part of `path`, whole segments from the start, that is a
/// field of the schema; `.` if none is.
pub fn known_prefix(path: &str) -> &str {
    let mut cut = path.len();
    loop {
        let prefix = &path[..cut];
        if field_of(prefix).is_some() {
            return prefix;
        }
        match prefix.rfind(['.', '[']) {
            Some(i) if i > 0 => cut = i,
            _ => return ".",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each field's own name appears in the schema's document.
    #[test]
    fn every_field_is_documented() {
        let doc = include_str!("../../../../docs/scene-schema.md");
        for field in FIELDS {
            let name = field
                .split(['.', '[', ']'])
                .rfind(|s| !s.is_empty() && *s != "*")
                .unwrap();
            let named = [
                format!("`{name}`"),
                format!("`{name}."),
                format!(".{name}`"),
            ];
            assert!(
                named.iter().any(|n| doc.contains(n.as_str())),
                "{field}: `{name}` undocumented"
            );
        }
    }

    #[test]
    fn paths_are_matched_and_trimmed_to_a_field() {
        assert_eq!(
            field_of("objects[12].center[2]"),
            Some("objects[].center[]")
        );
        assert_eq!(field_of("materials.a.b[0].eta"), Some("materials.*.eta"));
        assert_eq!(field_of("objects[x]"), None);
        assert_eq!(known_prefix("objects[0].radiux"), "objects[0]");
        assert_eq!(known_prefix(" bjects[0]"), ".");
        assert_eq!(known_prefix("render.spp"), "render.spp");
    }
}
