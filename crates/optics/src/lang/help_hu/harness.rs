//! The Hungarian of what the cross-check harness (feature `harness`)
//! adds: the commands `validate`, `compare`, `tradeoff` and
//! `tradeoff-job`, and `render`'s error budget.

use super::slot::Slot;

/// `validate`, `compare`, `tradeoff`, `tradeoff-job`.
pub(super) const HARNESS: &[Slot] = &[
    (&[], "threads", "Munkaszálak száma (alapértelmezés: minden mag)"),
    (
        &["validate"],
        "#about",
        "A törvények, a spektrumok és a renderelések összevetése a referenciákkal",
    ),
    (
        &["validate"],
        "#after_help",
        "Példák:
  optics validate                      a referenciák újragenerálása a rögzített eszközökkel, ellenőrzés
  optics validate --quick              a tárolóban rögzített referenciák, újragenerálás nélkül (a CI ezt futtatja)
  optics validate --quick --no-python  Python nélkül: nincs telepítés, nincsenek ábrák
  optics --json validate --quick --out /tmp/validation
  optics validate --quick --checkout ~/src/optics

A csomag munkapéldányát olvassa: --checkout, különben $OPTICS_CHECKOUT, különben a
munkakönyvtárat tartalmazó munkapéldány. A report.json, report.html és figures/*.png
fájlokat a --out könyvtárba írja. Első használatkor létrehozza a Python-környezetet (--venv,
a python-checks/requirements.txt rögzíti); ez egyszer letölti a Mitsuba 3-at, a
`colour-science` és a matplotlib csomagot. Kilépési kód 1, ha bármely ellenőrzés sikertelen.",
    ),
    (
        &["validate"],
        "quick",
        "A szűkített készlet futtatása: ellenőrzés a tárolóban rögzített referenciákkal, \
         újragenerálásuk helyett",
    ),
    (
        &["validate"],
        "checkout",
        "A csomag munkapéldánya (benne a validation/reference/ és a python-checks/) \
         [alapértelmezés: $OPTICS_CHECKOUT, különben a munkakönyvtárat tartalmazó munkapéldány]",
    ),
    (
        &["validate"],
        "out",
        "A report.json, a report.html és a figures/ könyvtára (ha hiányzik, létrejön) \
         [alapértelmezés: validation/out a munkapéldányban]",
    ),
    (
        &["validate"],
        "venv",
        "A Python virtuális környezete; ha hiányzik, létrejön [alapértelmezés: .venv a munkapéldányban]",
    ),
    (
        &["validate"],
        "python",
        "A Python 3 értelmező, amely a környezetet létrehozza",
    ),
    (
        &["validate"],
        "no_python",
        "Python nélkül: ellenőrzés a tárolóban rögzített referenciákkal, ábrák nélkül",
    ),
    (
        &["validate"],
        "seed",
        "A Mitsuba által kiértékelt véletlen esetek kezdőértéke (seed)",
    ),
    (
        &["compare"],
        "#about",
        "Egy színtér renderelt képének (PNG vagy PFM) összevetése a sugárkövető referenciájával",
    ),
    (
        &["compare"],
        "#after_help",
        "Példák:
  optics compare mine.png --scene crates/tracer/scenes/gold_spheres.json
  optics compare mine.pfm --scene scene.json --diff diff.png
  optics --json compare mean.pfm --scene scene.json --variance var.pfm --samples 64

A színteret a sugárkövetővel az IMAGE méretében rendereli (a saját fizikai módszerével,
vagy a --integrator szerintivel), és képpontonként, csatornánként összeveti; a
sziluetteken lévő képpontokat kihagyja. Kilépési kód 1, ha a kép eltér. A próbákat és
tűréseiket lásd: docs/cli.md.",
    ),
    (
        &["compare"],
        "image",
        "Az ellenőrzendő kép: PNG (8 bites sRGB, ahogy az `optics render` írja) vagy PFM \
         (lineáris sugársűrűség, W/(sr m²) csatornánként)",
    ),
    (
        &["compare"],
        "scene",
        "A színtérfájl, amelyről a kép készült",
    ),
    (
        &["compare"],
        "variance",
        "Az IMAGE sugársűrűségének mintánkénti szórásnégyzete, vele azonos méretű PFM; az IMAGE \
         ekkor képpontonként --samples minta átlaga",
    ),
    (
        &["compare"],
        "samples",
        "Minta képpontonként az IMAGE és a --variance mögött",
    ),
    (
        &["compare"],
        "diff",
        "Ide írja a különbségtérképet, egy IMAGE méretű PNG-t",
    ),
    (
        &["compare"],
        "integrator",
        "A referencia fényterjedési módszere (alapértelmezés: a színtéré); csak fizikai",
    ),
    (
        &["compare"],
        "reference_samples",
        "Egymintás (képpontonként egy minta) renderelések száma az útkövetett referencia mögött",
    ),
    (
        &["tradeoff"],
        "#about",
        "Megméri, mennyi pontosságba kerül és mennyi időt nyer minden egyszerűsítés, amelyet egy \
         színtér megenged",
    ),
    (
        &["tradeoff"],
        "#after_help",
        "Példák:
  optics tradeoff crates/tracer/scenes/kaleidoscope_lit.json --width 160 --height 120
  optics --json tradeoff crates/tracer/scenes/gold_spheres.json --repeats 5 --out /tmp/gold
  optics tradeoff crates/tracer/scenes/shadow.json --lambert --plan jobs.jsonl
  optics tradeoff crates/tracer/scenes/shadow.json --lambert --collect results

A SCENE.json (optics.tradeoff séma), a SCENE.md (a táblázat) és a SCENE-pareto.png (az idő
az egyes hibák függvényében, log-log skálán) fájlt a --out könyvtárba írja, a referenciaképet
pedig a --out/truth alá menti. A mértékeket lásd: docs/tradeoffs.md. A --plan ehelyett a
sorozat renderelési feladatait írja ki (mindegyik az `optics tradeoff-job` paranccsal
futtatható), a --collect pedig összefésüli az eredményeiket:
docs/cli.md, `Spread a sweep over machines` fejezet.",
    ),
    (
        &["tradeoff"],
        "spp",
        "Minta képpontonként a létra Monte Carlo módszereinél, ha a színtér saját módszere \
         determinisztikus",
    ),
    (
        &["tradeoff"],
        "truth_spp",
        "Minta képpontonként a referenciaképhez (két félben, mindkettő feleannyival)",
    ),
    (
        &["tradeoff"],
        "repeats",
        "Renderelések száma beállításonként: az idő ezek mediánja; a Monte Carlo beállítások \
         mindegyike új kezdőértéket kap, és kettő vagy több renderelés szétválasztja a \
         szórásnégyzetet a torzítástól",
    ),
    (
        &["tradeoff"],
        "min_seconds",
        "Minden beállítást addig renderel, amíg renderelései együtt ennyi másodpercig tartanak \
         (legfeljebb 64 renderelés), a stabilabb mediánért",
    ),
    (
        &["tradeoff"],
        "out",
        "Az eredmények és a referenciaképek gyorsítótárának könyvtára (ha hiányzik, létrejön)",
    ),
    (
        &["tradeoff"],
        "lambert",
        "A színtér mérése úgy, hogy course_rough anyagai kd albedójú Lambert-anyagok legyenek: a \
         csomag energiamegmaradó helyettesítése (a kurzus kd-je 1/sr egységű: diffúz albedója \
         π kd, a kurzus színtereiben 2.5-ig, és az egymást látó felületek között a fény \
         megsokszorozódik)",
    ),
    (
        &["tradeoff"],
        "fresh",
        "A referenciakép újrarenderelése akkor is, ha a gyorsítótárban van egyező",
    ),
    (
        &["tradeoff"],
        "no_plot",
        "A Pareto-ábra elhagyása (ehhez a .venv matplotlib csomagja kell)",
    ),
    (
        &["tradeoff"],
        "plan",
        "Nem renderel semmit: a sorozatot független feladatokként ebbe a fájlba írja, \
         feladatonként egy JSON-sorba, hogy az `optics tradeoff-job` bárhol futtathassa",
    ),
    (
        &["tradeoff"],
        "collect",
        "Nem renderel semmit: a terv feladatainak eredményeit (eredményfájlok könyvtárait vagy \
         magukat a fájlokat) a sorozat rekordjává fésüli össze; ugyanazt a színteret és \
         ugyanazokat a kapcsolókat kell megadni, mint a --plan mellett",
    ),
    (
        &["tradeoff-job"],
        "#about",
        "Az `optics tradeoff --plan` paranccsal tervezett sorozat egy feladatának futtatása",
    ),
    (
        &["tradeoff-job"],
        "#after_help",
        "Példák:
  optics tradeoff crates/tracer/scenes/shadow.json --lambert --plan jobs.jsonl
  optics tradeoff-job jobs.jsonl 3 --out results
  parallel optics tradeoff-job jobs.jsonl {} --out results ::: $(seq 0 26)
  sed -n 4p jobs.jsonl | optics tradeoff-job - --out results

A RESULTS/job-NNNN.json fájlt írja (optics.tradeoff-result séma), egyetlen sorban;
az `optics tradeoff SCENE [a terv kapcsolói] --collect RESULTS` fésüli össze őket.
Lásd: docs/cli.md, `Spread a sweep over machines` fejezet.",
    ),
    (
        &["tradeoff-job"],
        "jobs",
        "A terv (`optics tradeoff --plan`), JSONL formában; a `-` a szabványos bemenetet olvassa",
    ),
    (
        &["tradeoff-job"],
        "index",
        "A futtatandó feladat: a sora a JOBS-ban, 0-tól számolva (kötelező, ha a JOBS egynél \
         több sort tartalmaz)",
    ),
    (
        &["tradeoff-job"],
        "out",
        "Az eredmény könyvtára (ha hiányzik, létrejön)",
    ),
];

/// `render`'s error budget (`--tolerance` and the flags that go with it).
pub(super) const BUDGET: &[Slot] = &[
    (
        &["render"],
        "tolerance",
        "A legolcsóbb beállítások választása, amelyek becsült hibája (--metric) ez alatt marad: \
         pozitív, véges szám (a 0.05-ös relatív négyzetes középhiba 5 %). A költségkeret választja a \
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
];
