//! The Hungarian of every help text `optics` shows, one slot per text:
//! `(command path, key, Hungarian)`, read by [`super::help`], which says
//! what the keys are. A slot on a command also serves the same argument
//! and value keys in the commands below it, so a text shared by several
//! commands (a global flag, the scene flags of `render` and `inspect`) is
//! declared once, on the lowest command above all of them; a test checks
//! that every command reading a slot shows the same English there.
//!
//! A new flag, value or subcommand gets its Hungarian here, beside the
//! others of its command; until it does, the test that walks the parser
//! (`lang::tests`) fails and names its path and key. The examples in an
//! after-help keep their command lines verbatim; only the prose is
//! translated. `{laws}` stands for the law table's names, as in the
//! English of `batch`.

#[cfg(feature = "harness")]
mod harness;
mod laws;
mod quiz;
mod scene;
mod slot;

pub(crate) use slot::Slot;

/// Every slot, by the family of commands it belongs to.
pub(crate) static SLOTS: &[&[Slot]] = &[
    SHARED,
    quiz::QUIZ,
    quiz::ERRATA,
    laws::LAWS,
    scene::SCENE,
    #[cfg(feature = "harness")]
    harness::HARNESS,
    #[cfg(feature = "harness")]
    harness::BUDGET,
];

/// The program's own texts, its global and built-in flags, clap's `help`
/// subcommand, and the flags several commands share.
const SHARED: &[Slot] = &[
    (
        &[],
        "#about",
        "Optikai törvények, a kurzus kvíze és a kurzus sugárkövetői, egymással összevetve.",
    ),
    (
        &[],
        "#after_help",
        "Példák:
  optics quiz seed
  optics fresnel --eta 1.5 --theta-i-deg 60
  optics --json refract --wi 0,0.6,0.8 --normal 0,0,1 --eta 1.5
  optics envmap --dir -3.2,5.1,-8.4 --map cube
  optics --lang hu quiz f0 --n 1.4",
    ),
    (&[], "json", "Szöveg helyett egyetlen JSON-objektum kiírása"),
    (
        &[],
        "lang",
        "A szöveges kimenet nyelve: en (angol) vagy hu (magyar)",
    ),
    (&[], "lang=en", "angol"),
    (&[], "lang=hu", "magyar"),
    (
        &[],
        "help",
        "A súgó kiírása\n\nRövid összefoglaló: '-h'.",
    ),
    (&[], "version", "A verziószám kiírása"),
    (
        &["help"],
        "#about",
        "Ez a súgó, vagy a megadott alparancs(ok) súgója",
    ),
    (&[], "normal", "Felületi normálvektor (hossza tetszőleges)"),
    (
        &[],
        "light_dir",
        "A fényforrás felé mutató irány (hossza tetszőleges)",
    ),
    (
        &[],
        "radiance",
        "A fény L_in értéke: W/m² a fény felé forduló felületen",
    ),
    (&[], "ks", "Spekuláris együttható"),
    (&[], "shine", "Csillogási kitevő"),
    (
        &[],
        "wi",
        "A beeső fény felé mutató irány, a felülettől elfelé (hossza tetszőleges)",
    ),
    (&[], "plane_point", "A sík egy pontja"),
    (
        &[],
        "plane_normal",
        "A sík normálvektora (hossza tetszőleges, de nem nulla)",
    ),
    (
        &[],
        "scene",
        "A színtérfájl (JSON, lásd: docs/scene-schema.md)",
    ),
    (
        &[],
        "width",
        "A kép szélessége képpontban (alapértelmezés: a színtéré); a kamera látómezeje nem változik",
    ),
    (
        &[],
        "height",
        "A kép magassága képpontban (alapértelmezés: a színtéré)",
    ),
    (&[], "integrator=local", "Csak közvetlen fény; a tükrökben és az üvegben a háttér látszik"),
    (&[], "integrator=whitted", "Whitted-féle sugárkövetés: rekurzív tükrös visszaverődés és törés, árnyéksugarak"),
    (&[], "integrator=path", "Útkövetés: Monte Carlo globális megvilágítás"),
    (&[], "integrator=photon", "Az útkövető és egy kausztikus fotontérkép: a pontszerű fényforrások tükrökön és üvegen át a durva felületekre jutó fénye is"),
    (&[], "integrator=course", "Amit a kurzus végső GLSL-árnyalója számol, a hibáival együtt"),
];
