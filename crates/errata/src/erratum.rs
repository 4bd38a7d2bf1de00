//! One erratum of the course texts and the vocabulary it is written in:
//! its [`Class`], the [`Text`] it is in, [`Words`] in both languages.

use record::Lang;
use serde::{Deserialize, Serialize};

/// How bad an erratum is, worst first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Class {
    /// Wrong physics (or geometry) a student would learn from the text.
    Physics,
    /// Changes the picture a listing or shader draws, the homework's
    /// included.
    Picture,
    /// Typesetting, rounding, names: the physics and the picture stay.
    Cosmetic,
}

impl Class {
    /// Every class, worst first.
    pub const ALL: [Class; 3] = [Class::Physics, Class::Picture, Class::Cosmetic];

    /// The class's name, as the table and `--class` write it.
    pub fn name(self) -> &'static str {
        match self {
            Class::Physics => "physics",
            Class::Picture => "picture",
            Class::Cosmetic => "cosmetic",
        }
    }

    /// The class's name in `lang`.
    pub fn word(self, lang: Lang) -> &'static str {
        match self {
            Class::Physics => lang.pick("physics", "fizika"),
            Class::Picture => lang.pick("picture", "kép"),
            Class::Cosmetic => lang.pick("cosmetic", "kozmetikai"),
        }
    }

    /// What the class means, in `lang`.
    pub fn meaning(self, lang: Lang) -> &'static str {
        match self {
            Class::Physics => lang.pick(
                "wrong physics a student would learn",
                "hibás fizika, amit a hallgató megtanulna",
            ),
            Class::Picture => lang.pick(
                "changes the picture a listing or shader draws, the homework's included",
                "megváltoztatja a kódrészlet vagy shader által rajzolt képet, a házi feladatét is",
            ),
            Class::Cosmetic => lang.pick(
                "typesetting, rounding or names",
                "szedés, kerekítés vagy elnevezés",
            ),
        }
    }
}

/// One of the four course texts, by its prefix in `shared/seeds/`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Text {
    /// `000`, the GLSL ray tracer tutorial (Hungarian).
    #[serde(rename = "000")]
    Tutorial,
    /// `001`, the slides on realistic scenes (Hungarian).
    #[serde(rename = "001")]
    Slides,
    /// `002`, the WebGL ray tracer (English).
    #[serde(rename = "002")]
    WebGl,
    /// `003`, the textbook chapter with the quiz (Hungarian).
    #[serde(rename = "003")]
    Textbook,
}

impl Text {
    /// Every text, by prefix.
    pub const ALL: [Text; 4] = [Text::Tutorial, Text::Slides, Text::WebGl, Text::Textbook];

    /// The prefix, `000` to `003`.
    pub fn prefix(self) -> &'static str {
        match self {
            Text::Tutorial => "000",
            Text::Slides => "001",
            Text::WebGl => "002",
            Text::Textbook => "003",
        }
    }

    /// The file's name in `shared/seeds/`.
    pub fn file_name(self) -> &'static str {
        match self {
            Text::Tutorial => "000_94fadf09dcd8a81d.txt",
            Text::Slides => "001_4dd31754744da849.txt",
            Text::WebGl => "002_95b2536c50d9a590.txt",
            Text::Textbook => "003_4d80759929b48f79.txt",
        }
    }
}

/// A text in English and in Hungarian.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Words {
    /// English.
    pub en: String,
    /// Hungarian.
    pub hu: String,
}

impl Words {
    /// The text in `lang`.
    pub fn pick(&self, lang: Lang) -> &str {
        lang.pick(&self.en, &self.hu)
    }
}

/// One place where a course text disagrees with the laws.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Erratum {
    /// Stable id: the text's prefix, then a few words (`003-boxed-refraction`).
    pub id: String,
    /// How bad it is.
    pub class: Class,
    /// The text it is in.
    pub text: Text,
    /// The first and last line of the place, from 1.
    pub lines: [u32; 2],
    /// What is wrong, in a line.
    pub title: Words,
    /// What the text says, quoted (in the text's language).
    pub written: String,
    /// What is right, ready to paste back into the notes.
    pub right: Words,
    /// What it does, measured, with the index or inputs it assumes; none
    /// where the erratum has no number to it.
    pub effect: Option<Words>,
    /// The tests that demonstrate it, by function name.
    pub tests: Vec<String>,
}

impl Erratum {
    /// The place as people read it: `003:246`, `003:217–240`; in
    /// Hungarian `003, 246. sor`.
    pub fn place(&self, lang: Lang) -> String {
        let [first, last] = self.lines;
        let lines = if first == last {
            first.to_string()
        } else {
            format!("{first}–{last}")
        };
        match lang {
            Lang::En => format!("{}:{lines}", self.text.prefix()),
            Lang::Hu => format!("{}, {lines}. sor", self.text.prefix()),
        }
    }
}
