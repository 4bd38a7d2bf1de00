//! The Hungarian of the laws' help (`optics fresnel`, … `optics batch`).

use super::slot::Slot;

/// The Fresnel models: values of `fresnel --model` and of the scene
/// flags' `--fresnel`.
pub(super) const FRESNEL_EXACT: &str = "A pontos Fresnel-egyenletek";
pub(super) const FRESNEL_SCHLICK_INCIDENT: &str =
    "Schlick-közelítés a beesési szög koszinuszával, ahogy a kurzus írja: nem ismeri a teljes visszaverődést";
pub(super) const FRESNEL_SCHLICK_RARER: &str =
    "Schlick-közelítés a ritkább közegbeli szög koszinuszával: a teljes visszaverődés helyes";
pub(super) const FRESNEL_COURSE: &str =
    "A kurzus árnyalójának fordított alakja, hogy ennek a hibának (erratum) a hatása külön mérhető legyen";

/// The laws' own subcommands and `optics batch`.
pub(super) const LAWS: &[Slot] = &[
    (
        &["fresnel"],
        "#about",
        "Fresnel-féle visszaverődési tényező, pontosan vagy Schlick-közelítéssel, dielektrikumra vagy vezetőre",
    ),
    (
        &["fresnel"],
        "#after_help",
        "Példák:
  optics fresnel --eta 1.5 --theta-i-deg 60
  optics fresnel --eta 1.5 --cos-i -0.5           (az üveg belsejéből: teljes visszaverődés)
  optics fresnel --eta 0.17 --kappa 3.1 --cos-i 1 (arany, vörös csatorna, merőleges beesésnél)
  optics fresnel --metal course-gold --theta-i-deg 60 (mindhárom csatorna: R, G, B)
  optics fresnel --eta 1.5 --theta-i-deg 120 --model schlick-incident (nem ismeri a teljes visszaverődést)
  optics fresnel --eta 1.5 --cos-i 0.3 --model schlick-rarer --json",
    ),
    (
        &["fresnel"],
        "eta",
        "Relatív törésmutató, n_inside / n_outside (kívülről érkező fényre = n_t / n_i)",
    ),
    (
        &["fresnel"],
        "kappa",
        "A belső közeg extinkciós együtthatója; ha > 0, a közeg vezető (komplex törésmutató: eta + i·kappa)",
    ),
    (
        &["fresnel"],
        "metal",
        "Egy fém a nevével, --eta és --kappa helyett: a válasz RGB-csatornánként",
    ),
    (
        &["fresnel"],
        "metal=course-gold",
        "A kurzus aranya, `n = (0.17, 0.35, 1.5)`, `κ = (3.1, 2.7, 1.9)` (`000` forrás)",
    ),
    (&["fresnel"], "metal=gold", "Arany, mért érték"),
    (&["fresnel"], "metal=silver", "Ezüst, mért érték"),
    (&["fresnel"], "metal=copper", "Réz, mért érték"),
    (&["fresnel"], "metal=aluminium", "Alumínium, mért érték"),
    (
        &["fresnel"],
        "cos_i",
        "A beesési szög előjeles koszinusza, n·wi: > 0 kívülről, < 0 belülről",
    ),
    (
        &["fresnel"],
        "theta_i_deg",
        "Beesési szög a kifelé mutató normálistól, fokban, 0..180 (90 fölött: belülről)",
    ),
    (
        &["fresnel"],
        "model",
        "A törvény: a pontos, a Schlick-közelítés, vagy a kurzus árnyalójának fordított alakja",
    ),
    (&["fresnel"], "model=exact", FRESNEL_EXACT),
    (&["fresnel"], "model=schlick-incident", FRESNEL_SCHLICK_INCIDENT),
    (&["fresnel"], "model=schlick-rarer", FRESNEL_SCHLICK_RARER),
    (&["fresnel"], "model=course", FRESNEL_COURSE),
    (
        &["fresnel-bulk"],
        "#about",
        "Egy anyag pontos Fresnel-féle visszaverődési tényezője sok koszinuszra egyszerre",
    ),
    (
        &["fresnel-bulk"],
        "#after_help",
        "A válasz a visszaverődési tényezők listája, a koszinuszok sorrendjében; mindegyik bitre
ugyanaz, amit az `optics fresnel --model exact` ad arra a koszinuszra. Vezetőre
(--kappa > 0) csak kívülről érkezhet fény: minden koszinusz ≥ 0.

Példa:
  optics fresnel-bulk --eta 1.5 --cos-i 1,0.5,0,-0.5,-0.9
  printf '%s\\n' '{\"law\": \"fresnel_bulk\", \"eta\": 0.17, \"kappa\": 3.1, \"cos_i\": [1, 0.5, 0]}' | optics batch",
    ),
    (
        &["fresnel-bulk"],
        "eta",
        "Relatív törésmutató, n_inside / n_outside (vezetőnél az n)",
    ),
    (
        &["fresnel-bulk"],
        "kappa",
        "Extinkciós együttható, κ (dielektrikumnál 0)",
    ),
    (
        &["fresnel-bulk"],
        "cos_i",
        "A beesési szögek koszinuszai, vesszővel elválasztva (kérésben tömbként); > 0 kívülről",
    ),
    (
        &["refract"],
        "#about",
        "A megtört irány (a Snellius–Descartes-törvény vektoros alakja)",
    ),
    (
        &["refract"],
        "#after_help",
        "Az irányok a felülettől elfelé mutatnak: a --wi visszafelé, a fény forrása felé mutat,
a sugár pedig −wi irányban halad. A normálvektor kifelé mutat (az 1 törésmutatójú közeg felé).

Példák:
  optics refract --wi 0,0.6,0.8 --normal 0,0,1 --eta 1.5
  optics refract --wi 0,0.8,-0.6 --normal 0,0,1 --eta 1.5   (belülről, a határszögön túl)",
    ),
    (
        &["refract"],
        "normal",
        "Kifelé mutató felületi normálvektor (hossza tetszőleges)",
    ),
    (&["refract"], "eta", "Relatív törésmutató, n_inside / n_outside"),
    (&["reflect"], "#about", "A tükörirány"),
    (
        &["reflect"],
        "#after_help",
        "Az irányok a felülettől elfelé mutatnak.

Példa:
  optics reflect --wi 0,0.6,0.8 --normal 0,0,1",
    ),
    (
        &["shade"],
        "#about",
        "Egy BRDF által visszavert sugársűrűség irányfény megvilágításában",
    ),
    (
        &["shade"],
        "#after_help",
        "A fény irányfény: a --radiance a kurzus L_in értéke, a fény erőssége a felé forduló
felületen (W/m², a kurzus ezt nevezi sugársűrűségnek). Az irányok a felülettől elfelé mutatnak.

Példák:
  optics shade --model course-lambert --normal 0,0,1 --light-dir 0,3,4 --view-dir 1,2,3 --radiance 5 --kd 0.6
  optics shade --model blinn-phong --normal 0,0,1 --light-dir 0,3,4 --view-dir 0,4,3 --radiance 5 --ks 1.41421356 --shine 3",
    ),
    (
        &["shade"],
        "view_dir",
        "A néző felé mutató irány (hossza tetszőleges)",
    ),
    (&["shade"], "model", "A BRDF-modell"),
    (
        &["shade"],
        "model=lambert",
        "Fizikailag normált Lambert-modell, f = kd/π (kd az albedó)",
    ),
    (
        &["shade"],
        "model=course-lambert",
        "A kurzus Lambert-modellje, f = kd (1/π nélkül)",
    ),
    (
        &["shade"],
        "model=phong",
        "Phong-modell: f = kd + ks (cos⁺α)^shine / cos θi",
    ),
    (
        &["shade"],
        "model=blinn-phong",
        "A kurzus Phong-Blinn-modellje: f = kd + ks (cos⁺δ)^shine / cos θi",
    ),
    (
        &["shade"],
        "model=blinn-phong-reciprocal",
        "A kurzus reciprok javítása: f = kd + ks (cos⁺δ)^shine / |L+V|²",
    ),
    (
        &["shade"],
        "kd",
        "Diffúz együttható (`lambert` esetén az albedó)",
    ),
    (
        &["envmap"],
        "#about",
        "Hol olvasható ki egy visszavert irány a kocka-, a szélesség–hosszúság- vagy a gömbtérképből",
    ),
    (
        &["envmap"],
        "#after_help",
        "A --dir a visszavert r irány, amely a felülettől a környezet felé mutat (hossza
tetszőleges). A gömbtérképnél nézeti koordinátákban értendő: a néző a −z irányba néz.

Példák:
  optics envmap --dir -3.2,5.1,-8.4 --map cube     (a diák példája: a −Z lap)
  optics envmap --dir 1,1,0",
    ),
    (
        &["envmap"],
        "dir",
        "A visszavert r irány (hossza tetszőleges)",
    ),
    (
        &["envmap"],
        "map",
        "A térkép: `cube`, `lat-long`, `sphere` vagy `all`",
    ),
    (
        &["envmap"],
        "map=cube",
        "Kockatérkép: a kocka lapja és rajta az (u, v)",
    ),
    (
        &["envmap"],
        "map=lat-long",
        "Szélesség–hosszúság-térkép: (u, v) és a ρ, φ szögek",
    ),
    (
        &["envmap"],
        "map=sphere",
        "Gömbtérkép: (u, v), m és a gömb normálvektora",
    ),
    (&["envmap"], "map=all", "Mindhárom"),
    (
        &["reflection-matrix"],
        "#about",
        "A 4 × 4-es mátrix, amely a színteret egy síkra tükrözi",
    ),
    (
        &["reflection-matrix"],
        "#after_help",
        "A diák képlete: M = F⁻¹ S(1, −1, 1) F, F = R(n → y) T(−p): oszlopvektorok, M (x, y, z, 1).
A --point mellett M (p, 1): a pont tükörképe (a fényforrás helye is így tükröződik); a
--direction mellett M (w, 0): egy irány (egy irányfényé) tükrözve, eltolás nélkül.

Példa:
  optics reflection-matrix --plane-point 0,1,0 --plane-normal 0,1,0 --point 2,3,4   (az y = 1 padló)",
    ),
    (
        &["reflection-matrix"],
        "point",
        "Tükrözendő pont (egy fényforrás helye)",
    ),
    (
        &["reflection-matrix"],
        "direction",
        "Tükrözendő irány (egy irányfényé); hossza tetszőleges, de nem nulla",
    ),
    (
        &["shadow-matrix"],
        "#about",
        "A 4 × 4-es mátrix, amely a színtér árnyékát egy pontfényből egy síkra vetíti",
    ),
    (
        &["shadow-matrix"],
        "#after_help",
        "A diák árnyékmátrixa egy l pontfényből az n · x + d = 0 síkra: oszlopvektorok, M (x, y, z, 1),
osztva a w-vel. A --vertex mellett a kimenet megmondja, hogy esik-e oda árnyék (`cast`), vagy a
mátrix olyan helyre tesz pontot, ahová nem esik árnyék (`beyond_plane`, `behind_light`), vagy a
fényből induló egyenes sosem metszi a síkot (`parallel`). A síkon fekvő fény (n · l + d = 0)
szingulárissá teszi a mátrixot: minden csúcs a fényforrásba kerül (`degenerate`).

Példa:
  optics shadow-matrix --light 0,4,0 --plane-point 0,0,0 --plane-normal 0,1,0 --vertex 1,2,0",
    ),
    (&["shadow-matrix"], "light", "A pontfény helye"),
    (&["shadow-matrix"], "vertex", "A síkra vetítendő csúcs"),
    (
        &["batch"],
        "#about",
        "JSONL-kérések kiértékelése a szabványos bemenetről, soronként egy JSON-eredmény",
    ),
    (
        &["batch"],
        "#after_help",
        "A kérések JSON-objektumok, soronként egy; a \"law\" értéke ezek egyike:
  {laws}
a többi mező pedig az alparancs kapcsolói, '-' helyett '_' jellel, a vektorok [x, y, z] alakban.
A kérés saját \"steps\": `true` vagy `false` mezője arra a sorra felülírja a --no-steps kapcsolót.

Példák:
  printf '%s\\n' '{\"law\": \"fresnel\", \"eta\": 1.5, \"cos_i\": 0.3}' \\
                '{\"law\": \"refract\", \"wi\": [0, 0.6, 0.8], \"normal\": [0, 0, 1], \"eta\": 1.5}' | optics batch
  printf '%s\\n' '{\"law\": \"fresnel\", \"eta\": 1.5, \"cos_i\": 0.3}' \\
                '{\"law\": \"f0\", \"n\": 1.5, \"steps\": true}' | optics batch --no-steps

Kilépési kód: 0, ha minden sor kiértékelhető volt, 1, ha bármelyik sor hibaobjektumot adott.",
    ),
    (
        &["batch"],
        "block",
        "Ennyi sort értékel ki együtt, párhuzamosan, mielőtt az eredményeiket kiírja",
    ),
    (
        &["batch"],
        "no_steps",
        "A levezetés elhagyása: minden rekord \"steps\" mezője [] (a kérés saját \"steps\" mezője ezt felülírja)",
    ),
];
