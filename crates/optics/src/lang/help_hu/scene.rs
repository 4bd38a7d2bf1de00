//! The Hungarian of `optics render` and `optics inspect`, whose scene
//! flags (`--integrator`, `--spp`, …) are declared once, on the root, for
//! both.

use super::laws::{FRESNEL_COURSE, FRESNEL_EXACT, FRESNEL_SCHLICK_INCIDENT, FRESNEL_SCHLICK_RARER};
use super::slot::Slot;

/// `render`, `inspect` and the scene flags they share.
pub(super) const SCENE: &[Slot] = &[
    (
        &[],
        "integrator",
        "Fényterjedési módszer (alapértelmezés: a színtéré)",
    ),
    (
        &[],
        "spp",
        "Minta képpontonként (az útkövetőé; a többi módszer determinisztikus)",
    ),
    (
        &[],
        "max_depth",
        "Az első találat után megengedett visszapattanások száma",
    ),
    (&[], "fresnel", "A tükrök és az üveg Fresnel-modellje"),
    (&[], "fresnel=exact", FRESNEL_EXACT),
    (&[], "fresnel=schlick-incident", FRESNEL_SCHLICK_INCIDENT),
    (&[], "fresnel=schlick-rarer", FRESNEL_SCHLICK_RARER),
    (&[], "fresnel=course", FRESNEL_COURSE),
    (
        &[],
        "pixel_filter",
        "Hol haladnak át az elsődleges sugarak a képpontjukon (alapértelmezés: a színtéré, \
         különben `path` esetén `box`, a többinél `center`)",
    ),
    (
        &[],
        "pixel_filter=box",
        "Rétegzett sugarak a képpont egész területén, átlagolva (a `path` alapértelmezése)",
    ),
    (
        &[],
        "pixel_filter=center",
        "Sugarak a képpont középpontján át, ahogy a kurzus árnyalóiban (a többi módszer alapértelmezése)",
    ),
    (&[], "seed", "Az útkövető véletlenszámainak kezdőértéke (seed)"),
    (
        &[],
        "precision",
        "A sugárkövető számolásának pontossági szintje (alapértelmezés: a színtéré, különben f32); \
         f64 csak `local` és `whitted` esetén",
    ),
    (
        &[],
        "precision=f32",
        "Egyszeres pontosság (minden módszerrel)",
    ),
    (
        &[],
        "precision=f64",
        "Dupla pontosság (csak `local` és `whitted` esetén)",
    ),
    (
        &[],
        "photons",
        "Fotonok száma menetenként a `photon` módszer kausztikus térképében",
    ),
    (
        &[],
        "photon_passes",
        "A kausztikus térkép meneteinek száma; mindegyik saját fotonokkal és kisebb sugárral \
         (fotonok × menetek legfeljebb 2^22)",
    ),
    (
        &[],
        "photon_radius",
        "A kausztikus térkép gyűjtési sugara az első menetben, m",
    ),
    (
        &[],
        "allow_expensive",
        "Renderelés akkor is, ha a becsült sugárszám meghaladja a 10¹²-t (órák); 10¹⁰ fölött a \
         becslés a renderelés előtt megjelenik",
    ),
    (
        &["render"],
        "#about",
        "Színtérfájl renderelése PNG-képbe és lebegőpontos képbe",
    ),
    (
        &["render"],
        "#after_help",
        "Példák:
  optics render crates/tracer/scenes/kaleidoscope.json -o kaleidoscope.png
  optics render crates/tracer/scenes/gold_spheres.json -o gold.png --integrator course
  optics --json render scene.json -o out.png --integrator path --spp 64 --seed 7 --threads 2
  optics render crates/tracer/scenes/glass_spheres.json -o caustics.png --integrator photon --spp 64
  optics render crates/tracer/scenes/kaleidoscope_lit.json -o k.png --tolerance 0.05 --metric rel_rmse --verify

Kiírja a PNG-t (sRGB, a sugársűrűség [0, 1]-re vágva: lásd docs/scene-schema.md), mellé
pedig azonos néven PFM-ként a lineáris sugársűrűséget.",
    ),
    (
        &["render"],
        "output",
        "A kiírandó PNG; a PFM mellé kerül, .pfm kiterjesztéssel",
    ),
    (
        &["render"],
        "threads",
        "Munkaszálak száma (alapértelmezés: minden mag). A kép nem függ tőle",
    ),
    (
        &["inspect"],
        "#about",
        "Megmutatja, milyen hatásokat igényel egy színtér, és mit hagy ki a renderelő",
    ),
    (
        &["inspect"],
        "#after_help",
        "Példák:
  optics inspect crates/tracer/scenes/shadow.json
  optics --json inspect crates/tracer/scenes/kaleidoscope.json --integrator path --spp 16
  optics inspect crates/tracer/scenes/gold_spheres.json --integrator path --spp 16 --measure

A költségeket a színtér kétszeri vagy többszöri renderelése méri, a saját méretében (vagy
--width/--height méretben): csak a szükséges részekkel, majd egyenként minden kihagyott
rész visszakapcsolásával. A képeket összeveti: a kihagyás egyetlen képpontot sem változtathat meg.",
    ),
    (&["inspect"], "scene", "A színtérfájl (JSON)"),
    (
        &["inspect"],
        "measure",
        "Méri, a fény mekkora részét nem látja a path integrátor ezen a színtéren: a path és a \
         photon integrátorral is négyszer rendereli a saját beállításaival (ahol a színtérben van \
         olyan fény, amelyet a path nem talál)",
    ),
];
