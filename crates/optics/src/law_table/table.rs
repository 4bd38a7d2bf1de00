//! The table itself: one line a law, and what the macro makes of it (the
//! subcommands, the batch's reading, the names, the dispatch).

use crate::envmap::EnvmapArgs;
use crate::error::Result;
use crate::input::Via;
use crate::laws::{FresnelArgs, FresnelBulkArgs, ReflectArgs, RefractArgs, ShadeArgs};
use crate::planar::{ReflectionMatrixArgs, ShadowMatrixArgs};
use crate::quiz::{BlinnPhongArgs, CriticalAngleArgs, F0Args, LambertArgs};
use record::{Lang, Record, Steps};
use serde::{Deserialize, Deserializer};

/// Declares the laws: those that are subcommands of their own, then those
/// of `optics quiz`. Each is `/// what it answers` (its `--help` line),
/// `"batch_name" Variant(Args)`.
macro_rules! laws {
    (
        commands { $( #[doc = $cdoc:literal] $cname:literal $cvariant:ident($cargs:ty), )* }
        quiz { $( #[doc = $qdoc:literal] $qname:literal $qvariant:ident($qargs:ty), )* }
    ) => {
        /// The laws that are subcommands of `optics` itself.
        #[derive(clap::Subcommand, Debug)]
        pub enum LawCommand {
            $( #[doc = $cdoc] $cvariant($cargs), )*
        }

        /// The laws that are exercises of `optics quiz`.
        #[derive(clap::Subcommand, Debug)]
        pub enum QuizLaw {
            $( #[doc = $qdoc] $qvariant($qargs), )*
        }

        /// The arguments of any law, as `optics batch` reads them.
        #[derive(Debug)]
        pub enum Law {
            $( #[doc = $cdoc] $cvariant($cargs), )*
            $( #[doc = $qdoc] $qvariant($qargs), )*
        }

        /// The laws a request may name, in the order `--help` lists them.
        pub const LAWS: &[&str] = &[$($cname,)* $($qname,)*];

        /// The laws that are exercises of `optics quiz`, by their request names.
        pub const QUIZ_LAWS: &[&str] = &[$($qname,)*];

        $( impl $cargs {
            /// The law's name in a request and in its record.
            pub const LAW: &'static str = $cname;
        } )*
        $( impl $qargs {
            /// The law's name in a request and in its record.
            pub const LAW: &'static str = $qname;
        } )*

        impl Law {
            /// The arguments of the law `name` read from `fields`; `None`
            /// for a name that is not one of [`LAWS`].
            pub fn read<'de, D: Deserializer<'de>>(
                name: &str,
                fields: D,
            ) -> Option<std::result::Result<Self, D::Error>> {
                Some(match name {
                    $( $cname => <$cargs>::deserialize(fields).map(Law::$cvariant), )*
                    $( $qname => <$qargs>::deserialize(fields).map(Law::$qvariant), )*
                    _ => return None,
                })
            }

            /// Evaluates the law, its inputs named as `via` says.
            pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
                match self {
                    $( Law::$cvariant(args) => args.solve(via, lang, steps), )*
                    $( Law::$qvariant(args) => args.solve(via, lang, steps), )*
                }
            }
        }

        impl LawCommand {
            /// Evaluates the law given on the command line.
            pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
                match self {
                    $( LawCommand::$cvariant(args) => args.solve(via, lang, steps), )*
                }
            }
        }

        impl QuizLaw {
            /// Evaluates the exercise given on the command line.
            pub fn solve(&self, via: Via, lang: Lang, steps: Steps) -> Result<Record> {
                match self {
                    $( QuizLaw::$qvariant(args) => args.solve(via, lang, steps), )*
                }
            }
        }
    };
}

laws! {
    commands {
        /// Fresnel reflectance, exact or Schlick, dielectric or conductor.
        "fresnel" Fresnel(FresnelArgs),
        /// Exact Fresnel reflectance of one material at many cosines at once.
        "fresnel_bulk" FresnelBulk(FresnelBulkArgs),
        /// The refracted direction (Snell's law in vector form).
        "refract" Refract(RefractArgs),
        /// The mirror direction.
        "reflect" Reflect(ReflectArgs),
        /// Radiance reflected by a BRDF under a directional light.
        "shade" Shade(ShadeArgs),
        /// Where a reflected direction is looked up in a cube, lat-long or sphere map.
        "envmap" Envmap(EnvmapArgs),
        /// The 4 × 4 matrix that mirrors a scene in a plane.
        "reflection_matrix" ReflectionMatrix(ReflectionMatrixArgs),
        /// The 4 × 4 matrix that projects a scene's shadow from a point light onto a plane.
        "shadow_matrix" ShadowMatrix(ShadowMatrixArgs),
    }
    quiz {
        /// Reflectance at normal incidence, F0, from the refractive index.
        "f0" F0(F0Args),
        /// Radiance reflected by the course's Lambert surface under a directional light.
        "lambert" Lambert(LambertArgs),
        /// The critical angle of total internal reflection, from a medium into air.
        "critical_angle" CriticalAngle(CriticalAngleArgs),
        /// Radiance reflected by the course's Phong-Blinn surface under a directional light.
        "blinn_phong" BlinnPhong(BlinnPhongArgs),
    }
}

/// The words of the command line before a law's flags: `fresnel`,
/// `quiz f0`, ….
pub fn command_words(law: &str) -> Vec<String> {
    let subcommand = law.replace('_', "-");
    if QUIZ_LAWS.contains(&law) {
        vec!["quiz".to_owned(), subcommand]
    } else {
        vec![subcommand]
    }
}
