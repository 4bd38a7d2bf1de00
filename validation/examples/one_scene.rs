use validation::checkout::Checkout;
use validation::reference::committed_dir;
use validation::renders::{self, MitsubaRenders, RenderChecks};
use validation::suite::Context;
fn main() {
    let names: Vec<String> = std::env::args().skip(1).collect();
    let quick = std::env::var("QUICK").is_ok();
    let mut reference = MitsubaRenders::load(&committed_dir()).expect("committed reference");
    reference.scenes.retain(|s| names.contains(&s.name));
    let (mut checks, mut figures) = (Vec::new(), Vec::new());
    let context = Context {
        reference_dir: committed_dir(),
        checkout: Checkout::at_build_time().root().to_owned(),
        quick,
    };
    let t = std::time::Instant::now();
    fn centre(
        scene: &tracer::scene::Scene,
        settings: &tracer::scene::Settings,
    ) -> Result<tracer::render::Image, String> {
        let mut settings = *settings;
        if settings.integrator == tracer::scene::IntegratorKind::Path {
            settings.pixel_filter = tracer::scene::PixelFilter::Center;
        }
        renders::tracer_render(scene, &settings)
    }
    let render: renders::Renderer = if std::env::var("CENTRE").is_ok() {
        centre
    } else {
        renders::tracer_render
    };
    RenderChecks { render }
        .run_all(&reference, &context, &mut checks, &mut figures)
        .unwrap();
    for c in &checks {
        println!("{:?}", c);
    }
    eprintln!("{:.1} s", t.elapsed().as_secs_f64());
}
