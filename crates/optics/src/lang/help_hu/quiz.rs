//! The Hungarian of the help of the course's quiz and errata (`optics quiz
//! …`, `optics errata`).

use super::slot::Slot;

/// `optics quiz` and its exercises.
pub(super) const QUIZ: &[Slot] = &[
    (
        &["quiz"],
        "#about",
        "A kurzus kvízének feladatai, lépésenként kidolgozva",
    ),
    (
        &["quiz"],
        "#after_help",
        "Példák:
  optics quiz                 (felsorolja a feladatokat)
  optics quiz seed            (a kurzus kvízének minden kérdését kidolgozza)
  optics quiz f0 --n 1.4
  optics --lang hu quiz seed",
    ),
    (
        &["quiz", "seed"],
        "#about",
        "A kurzus kvízének minden kérdése, a közölt válaszok ellenőrzésével",
    ),
    (
        &["quiz", "seed"],
        "#after_help",
        "Példák:
  optics quiz seed
  optics --lang hu quiz seed          (a kurzus nyelvén)
  optics --json quiz seed             (egyetlen JSON-objektum; a kérdések a details.questions alatt)",
    ),
    (
        &["quiz", "f0"],
        "#about",
        "Merőleges beesésű visszaverődés (F0) a törésmutatóból",
    ),
    (
        &["quiz", "f0"],
        "#after_help",
        "Példa (a kvíz 2. kérdése):
  optics quiz f0 --n 1.4",
    ),
    (
        &["quiz", "f0"],
        "n",
        "Törésmutató (a külső közeghez viszonyítva)",
    ),
    (
        &["quiz", "f0"],
        "kappa",
        "Extinkciós együttható (dielektrikumnál 0)",
    ),
    (
        &["quiz", "lambert"],
        "#about",
        "A kurzus Lambert-felületéről visszavert sugársűrűség irányfény megvilágításában",
    ),
    (
        &["quiz", "lambert"],
        "#after_help",
        "Példa (a kvíz 3. kérdése):
  optics quiz lambert --normal 0,0,1 --light-dir 0,3,4 --view-dir 1,2,3 --radiance 5 --kd 0.6",
    ),
    (
        &["quiz", "lambert"],
        "view_dir",
        "A kamera felé mutató irány (hossza tetszőleges; elhagyható: a Lambert-felület minden \
         fölötte lévő irányból egyformán látszik, alulról pedig semmi sem látszik)",
    ),
    (
        &["quiz", "lambert"],
        "kd",
        "A kurzus diffúz együtthatója, kd (f_r = kd, 1/π nélkül)",
    ),
    (
        &["quiz", "critical-angle"],
        "#about",
        "A teljes visszaverődés határszöge egy közegből levegőbe lépő fényre",
    ),
    (
        &["quiz", "critical-angle"],
        "#after_help",
        "Példa (a kvíz 4. kérdése: törésmutató 1/0.1 = 10, levegőbe):
  optics quiz critical-angle --n 10",
    ),
    (
        &["quiz", "critical-angle"],
        "n",
        "Annak a közegnek a törésmutatója, amelyből a fény érkezik",
    ),
    (
        &["quiz", "critical-angle"],
        "n_outside",
        "A határfelületen túli közeg törésmutatója (levegő: 1)",
    ),
    (
        &["quiz", "blinn-phong"],
        "#about",
        "A kurzus Phong-Blinn-felületéről visszavert sugársűrűség irányfény megvilágításában",
    ),
    (
        &["quiz", "blinn-phong"],
        "#after_help",
        "Példa (a kvíz 5. kérdése):
  optics quiz blinn-phong --normal 0,0,1 --light-dir 0,3,4 --view-dir 0,4,3 --radiance 5 --ks 1.41421356 --shine 3",
    ),
    (
        &["quiz", "blinn-phong"],
        "view_dir",
        "A kamera felé mutató irány (hossza tetszőleges)",
    ),
    (&["quiz", "blinn-phong"], "kd", "Diffúz együttható"),
];

/// `optics errata`.
pub(super) const ERRATA: &[Slot] = &[
    (
        &["errata"],
        "#about",
        "A kurzus szövegeinek hibái osztály szerint rangsorolva, vagy egy közülük az azonosítója szerint",
    ),
    (
        &["errata"],
        "#after_help",
        "Példák:
  optics errata                              (minden hiba, a fizikaiak elöl)
  optics errata --class physics
  optics --lang hu errata 003-boxed-refraction   (ami helyes, magyarul)
  optics --json errata --class cosmetic      (egyetlen JSON-objektum; a hibák a válaszmezőben)

Osztályok: physics (fizika: hibás fizika, amit a hallgató megtanulna), picture (kép: megváltoztatja
a programlista vagy az árnyaló rajzolta képet), cosmetic (kozmetikai: szedés, kerekítés, nevek).
A táblázat: crates/errata/errata.json; a docs/errata.md ebből készül.",
    ),
    (
        &["errata"],
        "id",
        "Egy hiba azonosítója, ahogy a lista mutatja (`003-boxed-refraction`); nélküle minden hiba, rangsorban",
    ),
    (
        &["errata"],
        "class",
        "Csak ennek az osztálynak a hibái: physics, picture vagy cosmetic (vagy fizika, kép, kozmetikai)",
    ),
];
