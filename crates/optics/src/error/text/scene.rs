//! A scene the tracer refused: the file, the JSON path and what is wrong.
//! The English of what is wrong is the tracer's `Display`, its Hungarian
//! an exhaustive `match` over the tracer's kinds; the advice on the flags
//! that settle it is the command's own, in both languages side by side.

use std::path::Path;

use record::Lang;
use techniques::bump::{FieldError, MAX_SLOPE, MIN_PERIOD};
use tracer::scene::error::{ImageProblem, JsonType, SizeRule};
use tracer::scene::{ErrorKind as Scene, FresnelModel, SceneError, MAX_PIXELS, SCHEMA_VERSION};

use super::domain::domain;

/// A refused scene in `lang`: the file, the JSON path (where the message
/// does not name its subject itself), what is wrong, and the advice.
pub(super) fn scene(file: &Path, error: &SceneError, lang: Lang) -> String {
    let file = file.display();
    let advice = advice(error.kind(), lang);
    let what = match lang {
        Lang::En => return format!("scene {file}: {error}{advice}"),
        Lang::Hu => scene_kind_hu(error.kind()) + advice,
    };
    match error.kind() {
        Scene::Read { .. } | Scene::Domain(_) => format!("a(z) {file} jelenet: {what}"),
        _ if error.field() == "." => format!("a(z) {file} jelenet: {what}"),
        _ => format!("a(z) {file} jelenet: {}: {what}", error.field()),
    }
}

/// The flags that settle a refused scene, for the commands that take
/// them: the tracer names the values, the command line its flags. Empty
/// for the other kinds.
fn advice(kind: &Scene, lang: Lang) -> &'static str {
    match kind {
        Scene::TooExpensive { .. } => lang.pick(
            "; optics render and inspect take --allow-expensive to render it anyway",
            "; az optics render és az inspect a --allow-expensive kapcsolóval mégis rendereli",
        ),
        Scene::CourseHasNoRefraction => lang.pick(
            "; choose one with --integrator whitted or path (render, inspect, compare) or \
             the scene's render.integrator",
            "; a --integrator whitted vagy path kapcsolóval (render, inspect, compare) vagy a \
             jelenet render.integrator mezőjében választható",
        ),
        _ => "",
    }
}

/// What is wrong with a refused scene, in Hungarian.
pub(super) fn scene_kind_hu(kind: &Scene) -> String {
    match kind {
        Scene::Read { source, .. } => format!("nem olvasható: {source}"),
        Scene::NotUtf8 { line, column } => {
            format!("nem UTF-8 szöveg: nem UTF-8 bájt a(z) {line}. sor {column}. oszlopában")
        }
        Scene::WrongShape { expected, got } => wrong_shape_hu(*expected, *got),
        Scene::Syntax {
            message,
            line,
            column,
        } => format!("hibás JSON ({line}. sor, {column}. oszlop): {message}"),
        Scene::Schema { message } => {
            format!("nem felel meg a jelenetleírás sémájának: {message}")
        }
        Scene::TypeMissing => "hiányzik: minden kamera, anyag, objektum és fény megnevezi a \
                               fajtáját (\"type\")"
            .to_owned(),
        Scene::TypeNotString { got } => {
            format!("a fajtát megnevező szövegnek kell lennie, kapott érték: {got}")
        }
        Scene::Version { got } => format!(
            "ez a sugárkövető a(z) {SCHEMA_VERSION}. változatú jelenetleírást olvassa, \
             kapott változat: {got}"
        ),
        Scene::NotACount { value, min, max } => {
            format!("{min} és {max} közötti egész számnak kell lennie, kapott érték: {value}")
        }
        Scene::TooManyPixels { width, height } => {
            format!("{width} × {height} képpont több a megengedett {MAX_PIXELS} képpontnál")
        }
        Scene::Domain(error) => domain(error, Lang::Hu),
        Scene::DirectionUnrepresentable => "f32-ben ábrázolható iránynak kell lennie".to_owned(),
        Scene::TargetIsEye => "különböznie kell a camera.eye értékétől".to_owned(),
        Scene::UpAlongView => "nem lehet párhuzamos a nézés irányával".to_owned(),
        Scene::FieldOfView { degrees } => {
            format!("a (0, 180) fok tartományba kell esnie, kapott érték: {degrees}")
        }
        Scene::FarNotBeyondNear { near, far } => {
            format!("a camera.near ({near}) mögött kell lennie, kapott érték: {far}")
        }
        Scene::UnknownMaterial { name, defined } => {
            format!("nincs {name:?} nevű anyag; a jelenet anyagai: {defined:?}")
        }
        Scene::RadianceOverflow { bound } => radiance_overflow_hu(*bound),
        Scene::LightWithinRounding {
            distance,
            rounding,
            widest,
        } => light_within_rounding_hu(*distance, *rounding, *widest),
        Scene::TooExpensive { rays } => too_expensive_hu(*rays),
        Scene::DielectricWithoutInside => "a dielektrikumhoz belső térrel bíró zárt felület \
                                           kell: csak gömb lehet dielektrikum"
            .to_owned(),
        Scene::CourseHasNoRefraction => "a kurzus árnyalójában nincs fénytörés: a \
                                         dielektrikumokat a whitted és a path integrátor \
                                         rendereli"
            .to_owned(),
        Scene::PrecisionNotServed {
            precision,
            integrator,
        } => format!(
            "a(z) {integrator} integrátor nem számol {precision} pontossággal: az f64 \
             pontosság a local és a whitted integrátoré; a path, a photon és a course f32"
        ),
        Scene::Bump(error) => bump_hu(error),
        Scene::BumpOnSmoothSurface => "a felületi egyenetlenség leképezése csak érdes és \
                                       megvilágítatlan anyagok árnyalását hajlítja, a \
                                       fémekét és a dielektrikumokét nem"
            .to_owned(),
        Scene::EnvironmentImage { file, problem } => {
            format!("{file} {}", image_problem_hu(problem))
        }
        Scene::BackgroundWithEnvironment => "a környezet helyettesíti a hátteret: a background \
                                             és az environment közül csak az egyiket kell \
                                             megadni"
            .to_owned(),
        Scene::SchlickFormUnnamed => schlick_form_unnamed(Lang::Hu),
    }
}

/// The bare `schlick` refused, with both forms named: the tracer's
/// English, and its Hungarian; `optics fresnel --model` says the same.
pub(super) fn schlick_form_unnamed(lang: Lang) -> String {
    let [incident, rarer] = FresnelModel::SCHLICK_FORMS;
    match lang {
        Lang::En => Scene::SchlickFormUnnamed.to_string(),
        Lang::Hu => format!(
            "a \"schlick\" Schlick két alakja közül egyiket sem nevezi meg: \"{incident}\" (a \
             beesési szög koszinusza, ahogy a kurzus írja; nem ismeri a teljes visszaverődést) \
             vagy \"{rarer}\" (a ritkább közegbeli szög koszinusza; a teljes visszaverődés \
             helyes) adható meg"
        ),
    }
}

/// A bump map's height field refused, in Hungarian.
fn bump_hu(error: &FieldError) -> String {
    match error {
        FieldError::NotFinite { value, .. } => {
            format!("véges számnak kell lennie, kapott érték: {value}")
        }
        FieldError::PeriodTooShort { period } => format!(
            "legalább {MIN_PERIOD} (16 véges differencia lépés) kell legyen, kapott érték: \
             {period}"
        ),
        FieldError::TooSteep { slope, .. } => {
            format!("{slope:e} meredekséget ad, többet a megengedett {MAX_SLOPE:e} értéknél")
        }
    }
}

/// The scene's numbers bound a radiance past f32's range, in Hungarian.
fn light_within_rounding_hu(distance: f64, rounding: f64, widest: usize) -> String {
    format!(
        "a pontfényforrás {distance:.3e} m-re van a legközelebbi felülettől, a \
         metszéspontok f32-kerekítésén belül ({rounding:.3e} m, ezt a(z) {widest}. objektum \
         koordinátái szabják meg): a megvilágítása ott korlátlan; a fényt távolabb kell \
         vinni a felülettől, vagy a(z) {widest}. objektumot közelebb az origóhoz"
    )
}

fn wrong_shape_hu(expected: JsonType, got: JsonType) -> String {
    format!(
        "a várt JSON-típus: {}, a kapott: {}",
        json_type_hu(expected),
        json_type_hu(got)
    )
}

fn radiance_overflow_hu(bound: f64) -> String {
    format!(
        "a jelenet számai együtt legfeljebb {bound:.3e} W/(sr·m²) sugársűrűséget adnak, \
         ami kívül esik az f32 tartományán ({:.3e}): a fényeket vagy az együtthatókat \
         kisebbre kell venni",
        f32::MAX
    )
}

/// A render that may cast more rays than allowed unasked, in Hungarian.
fn too_expensive_hu(rays: f64) -> String {
    format!(
        "ez a kép legfeljebb {rays:.3e} sugarat indíthat, több a drága renderelés \
         engedélye nélkül megengedett {:e}-nál: csökkentse a max_depth, az spp értékét \
         vagy a méretet, vagy növelje a throughput_cutoff értékét",
        tracer::needs::MAX_RAYS
    )
}

fn image_problem_hu(problem: &ImageProblem) -> String {
    match problem {
        ImageProblem::Read(source) => format!("nem olvasható: {source}"),
        ImageProblem::Decode(message) => format!("nem dekódolható PNG: {message}"),
        ImageProblem::Pixels(format) => {
            format!("képpontjai {format} típusúak; a környezet 8 bites RGB vagy RGBA")
        }
        ImageProblem::Size {
            width,
            height,
            expected,
        } => {
            let rule = match expected {
                SizeRule::TwiceAsWideAsHigh => {
                    "a szélességi–hosszúsági térkép kétszer olyan széles, mint magas".to_owned()
                }
                SizeRule::Square => "a kocka lapja négyzet alakú".to_owned(),
                SizeRule::FourByThreeFaces => {
                    "a kockakereszt négy négyzet alakú lap széles és három magas".to_owned()
                }
                SizeRule::SideOfFirstFace(side) => {
                    format!("a kocka minden lapjának oldala az első lapé, {side} képpont")
                }
                SizeRule::AtMost(side) => {
                    format!("egyik oldala sem lehet több {side} képpontnál")
                }
            };
            format!("{width} × {height} képpontos; {rule}")
        }
    }
}

fn json_type_hu(t: JsonType) -> &'static str {
    match t {
        JsonType::Null => "null",
        JsonType::Bool => "logikai érték",
        JsonType::Number => "szám",
        JsonType::String => "szöveg",
        JsonType::Array => "tömb",
        JsonType::Object => "objektum",
    }
}
