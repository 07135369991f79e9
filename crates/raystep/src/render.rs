//! `raystep render SCENE.toml`: render a scene file to a PNG.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;

use raystep_render::{Progress, RenderOptions};
use raystep_scene::MAX_SIZE;
use raystep_world::Accelerate;

use crate::chapters::{CHAPTERS, find};
use crate::error::Error;
use crate::shown_path::shown;
use raystep_figure::{Chapter, Renderer};

/// The renderer of a scene outside any chapter folder: the most complete
/// tracer.
const DEFAULT_RENDERER: &str = "ch06";

/// What `raystep render` was asked to do: its command line.
#[derive(Debug, clap::Args)]
pub struct Options {
    /// The scene file, e.g. chapters/ch03-illumination/scenes/spheres.toml.
    pub scene: PathBuf,
    /// The PNG to write [default: <scene name>.png in the current folder].
    #[arg(long, value_name = "FILE.png")]
    pub out: Option<PathBuf>,
    /// Image size, overriding the scene's, e.g. 640x360.
    #[arg(long, value_name = "WxH")]
    pub size: Option<String>,
    /// Worker threads [default: one per core]; the image is the same for any number.
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Render with this chapter's tracer [default: the chapter folder holding the scene,
    /// else the latest].
    #[arg(long, value_name = "CHAPTER")]
    pub chapter: Option<String>,
    /// What searches the objects for each ray: the lecture's loop over
    /// every object (`brute`), chapter 8's bounding volume hierarchy
    /// (`bvh`, binned SAH), chapter 9's uniform grid (`grid`), chapter
    /// 10's kd-tree (`kdtree`, SAH) or chapter 10's rule for which of
    /// them a scene needs (`auto`); the image is the same.
    #[arg(long, value_enum, default_value_t = Accel::Brute)]
    pub accel: Accel,
}

/// `--accel`: what searches a world's objects for each ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Accel {
    /// The lecture's loop: every ray against every object (chapter 3).
    Brute,
    /// Chapter 8's bounding volume hierarchy, binned SAH with 16 bins.
    Bvh,
    /// Chapter 9's uniform grid: the resolution rule (3·∛N cells along
    /// the longest axis), objects listed by their boxes, mailboxing on.
    Grid,
    /// Chapter 10's kd-tree: SAH planes from sorted events, the chosen
    /// costs, mailboxing on.
    #[value(name = "kdtree")]
    KdTree,
    /// The rule of chapter 10: the structure the scene's objects call for,
    /// chosen from their boxes before building (`ch10::choose`).
    Auto,
}

impl Accel {
    /// Its name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Accel::Brute => "brute",
            Accel::Bvh => "bvh",
            Accel::Grid => "grid",
            Accel::KdTree => "kdtree",
            Accel::Auto => "auto",
        }
    }

    /// What builds it for a list of objects.
    pub fn accelerate(self) -> Accelerate {
        match self {
            Accel::Brute => |_| Arc::new(ch03::BruteForce),
            Accel::Bvh => |objects| {
                Arc::new(ch08::Bvh::for_objects(
                    objects,
                    ch08::Builder::BinnedSah { bins: 16 },
                ))
            },
            Accel::Grid => |objects| {
                Arc::new(ch09::Grid::for_objects(
                    objects,
                    ch09::Resolution::Rule,
                ))
            },
            Accel::KdTree => |objects| {
                Arc::new(ch10::KdTree::for_objects(
                    objects,
                    ch10::KdBuilder::SahEvents,
                    ch10::KdCosts::CHOSEN,
                ))
            },
            Accel::Auto => ch10::auto,
        }
    }
}

/// Runs `raystep render`.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    if options.threads == Some(0) {
        return Err(Error::Usage(
            "--threads 0: must be at least 1".to_string(),
        ));
    }
    let file = shown(&options.scene);
    let mut scene = raystep_scene::load(&options.scene)
        .map_err(|e| Error::Usage(e.to_string()))?;
    if let Some(size) = &options.size {
        (scene.width, scene.height) = parse_size(size)?;
    }
    let (name, renderer) = choose(options.chapter.as_deref(), &options.scene)?;
    let out = options
        .out
        .clone()
        .unwrap_or_else(|| default_out(&options.scene));
    let render_options = RenderOptions {
        threads: options.threads,
        progress: Progress::Auto,
    };
    let image =
        renderer(&scene, &file, &render_options, options.accel.accelerate())
            .map_err(Error::Usage)?;
    image
        .write_png(&out)
        .map_err(|e| Error::Usage(e.to_string()))?;
    println!(
        "wrote {} ({}×{}, {name} renderer, --accel {})",
        shown(&out),
        scene.width,
        scene.height,
        options.accel.name()
    );
    Ok(ExitCode::SUCCESS)
}

/// `640x360` (or `640×360`) → (640, 360), each side 1 ..= MAX_SIZE.
fn parse_size(size: &str) -> Result<(u32, u32), Error> {
    let bad = || {
        Error::Usage(format!(
            "--size {size}: expected WIDTHxHEIGHT, each 1 to {MAX_SIZE}, e.g. 640x360"
        ))
    };
    let (w, h) = size.split_once(['x', 'X', '×']).ok_or_else(bad)?;
    let w: u32 = w.trim().parse().map_err(|_| bad())?;
    let h: u32 = h.trim().parse().map_err(|_| bad())?;
    if !(1..=MAX_SIZE).contains(&w) || !(1..=MAX_SIZE).contains(&h) {
        return Err(bad());
    }
    Ok((w, h))
}

/// The renderer for `--chapter`, else the chapter folder holding the scene,
/// else the latest.
fn choose(
    chapter: Option<&str>, scene: &Path,
) -> Result<(&'static str, Renderer), Error> {
    let renderers: Vec<&Chapter> = CHAPTERS
        .iter()
        .copied()
        .filter(|c| c.renderer.is_some())
        .collect();
    let pick = |c: &Chapter| {
        (c.id, c.renderer.expect("only chapters with a renderer"))
    };
    if let Some(arg) = chapter {
        return Ok(pick(find(arg, &renderers)?));
    }
    let in_folder = scene
        .canonicalize()
        .ok()
        .and_then(|path| {
            path.ancestors()
                .filter_map(|a| a.file_name()?.to_str().map(str::to_string))
                .find(|name| name.starts_with("ch") && name.contains('-'))
        })
        .and_then(|folder| {
            renderers.iter().find(|c| folder.starts_with(c.id)).copied()
        });
    match in_folder {
        Some(chapter) => Ok(pick(chapter)),
        None => Ok(pick(find(DEFAULT_RENDERER, &renderers)?)),
    }
}

fn default_out(scene: &Path) -> PathBuf {
    let stem = scene
        .file_stem()
        .map_or("render".into(), |s| s.to_string_lossy());
    PathBuf::from(format!("{stem}.png"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes() {
        assert_eq!(parse_size("640x360").unwrap(), (640, 360));
        assert_eq!(parse_size("64×36").unwrap(), (64, 36));
        for bad in ["640", "0x10", "10x0", "5000x10", "axb", "-1x5"] {
            let message = parse_size(bad).unwrap_err().to_string();
            assert!(
                message.starts_with(&format!("--size {bad}: expected")),
                "{message}"
            );
        }
    }
}
