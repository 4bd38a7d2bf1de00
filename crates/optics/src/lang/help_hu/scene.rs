//! The Hungarian of `optics render` and `optics inspect`, whose scene
//! flags (`--integrator`, `--spp`, …) are declared once, on the root, for
//! both.

use super::laws::{FRESNEL_COURSE, FRESNEL_EXACT, FRESNEL_SCHLICK};
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
    (&[], "fresnel=schlick", FRESNEL_SCHLICK),
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
        &["render"],
        "tolerance",
        "A legolcsóbb beállítások választása, amelyek becsült hibája (--metric) ez alatt marad: \
         pozitív, véges szám (0.05 relatív négyzetes középhiba 5 %). A költségkeret választja a \
         módszert, a mintaszámot, a max_depth értékét, a Fresnel-modellt és a képpontszűrőt: \
         ezek egyikét se adja meg",
    ),
    (
        &["render"],
        "metric",
        "Amire a tűrés vonatkozik: a lineáris sugársűrűség relatív négyzetes középhibája, a \
         megjelenített kép ΔE2000 színkülönbségének átlaga vagy 99. percentilise, vagy ꟻLIP-átlaga, \
         ahogy az `optics tradeoff` méri őket",
    ),
    (
        &["render"],
        "metric=rel_rmse",
        "A lineáris sugársűrűség relatív négyzetes középhibája a felületi képpontokon",
    ),
    (
        &["render"],
        "metric=delta_e_mean",
        "A megjelenített kép ΔE2000 színkülönbségének átlaga",
    ),
    (
        &["render"],
        "metric=delta_e_p99",
        "A megjelenített kép ΔE2000 színkülönbségének 99. percentilise",
    ),
    (
        &["render"],
        "metric=flip_mean",
        "A megjelenített kép ꟻLIP-átlaga",
    ),
    (
        &["render"],
        "verify",
        "Az elért hiba mérése a referenciaképhez képest (amely --truth-spp mintával készül, vagy a \
         gyorsítótárból jön)",
    ),
    (
        &["render"],
        "lambert",
        "A színtér mérése és renderelése úgy, hogy course_rough anyagai kd albedójú \
         Lambert-anyagok legyenek, ahogy az `optics tradeoff --lambert` helyettesíti őket (a \
         kurzus kd-je 1/sr egységű: π kd albedója 1 fölé megy, és egyetlen referenciakép sem \
         konvergál); a --verify ekkor a megfelelő referenciaképet használja",
    ),
    (
        &["render"],
        "pilot_spp",
        "Minta képpontonként a próbamenetben, két félben",
    ),
    (
        &["render"],
        "truth_spp",
        "Minta képpontonként a --verify referenciaképéhez (két félben)",
    ),
    (
        &["render"],
        "truth_cache",
        "A referenciaképek gyorsítótára (közös az `optics tradeoff` paranccsal)",
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

A költségeket a színtér kétszeri vagy többszöri renderelése méri, a saját méretében (vagy
--width/--height méretben): csak a szükséges részekkel, majd egyenként minden kihagyott
rész visszakapcsolásával. A képeket összeveti: a kihagyás egyetlen képpontot sem változtathat meg.",
    ),
    (&["inspect"], "scene", "A színtérfájl (JSON)"),
];
