"""All the light of the course scenes, measured by Mitsuba 3 two independent
ways, beside what Mitsuba's ``path`` integrator finds with the delta lights
kept.

Regenerate (from the repository root; the output is byte-for-byte stable):

    .venv/bin/python python-checks/mitsuba_full_light.py

writes ``validation/reference/mitsuba_full_light.json`` (schema
``mitsuba-full-light/1``, described in ``validation/README.md``).
``mitsuba_full_light.py --deeper SCENE SPP`` prints the light tracer's and
the area lights' means on the ``diffuse`` region at SPP samples per pixel
and pass instead, for a comparison of more power than the reference's.

A point or directional light is a delta light, a mirror, a conductor or
smooth glass a delta surface: a path light -> delta surfaces -> diffuse
surface -> camera can only be found by aiming at the light through the
delta surfaces, which neither a shadow ray (it stops at the first one) nor a
sampled bounce (it never hits a point) does. Mitsuba's ``path`` misses it as
the suite's ``whitted`` and ``path`` do. Four estimates per scene, each
``PASSES`` independent renders (``mi.render``, box pixel filter, seeds
``0..PASSES``, ``SPP`` samples per pixel each):

- ``path``: Mitsuba's ``path`` on the scene as it is: what is missed.
- ``ptracer``: Mitsuba's light tracer, paths from the lights connected to the
  camera at every non-delta vertex: all light that reaches the camera
  directly from a diffuse surface (it cannot see through a delta surface, so
  it is compared only where the camera sees a diffuse surface).
- ``path_centres``: ``path`` again, through the pixel centres as the
  suite's tracer samples them (``CENTRE_SPP`` samples per pixel and pass),
  not over the pixel: the harness compares the tracer's ``path`` with it,
  and measures by it how far the box filter moves each region's mean.
- ``area``: Mitsuba's ``path`` with each delta light replaced by an area
  light of equal power, which a path tracer hits by its sampled bounces and
  so converges to all the light:

  - a point light of intensity I (W/sr) at p becomes a sphere of radius r
    centred on p with radiance I / (pi r^2): a Lambertian sphere of radiance
    L shows the projected area pi r^2 from every direction, so its intensity
    is pi r^2 L = I everywhere, and its power 4 pi I is the point light's.
    Seen from a point wholly above its horizon, the sphere's irradiance is
    exactly I cos(theta) / d^2 (the irradiance of a uniform sphere, as of a
    point at its centre); it differs only in penumbrae and where a mirror
    chain images it. r is ``ANGULAR_RADIUS`` times the distance from p to the
    nearest surface, so the sphere touches nothing.
  - a directional light of irradiance E (W/m^2 facing it) towards w becomes
    a disk facing the scene, ``DISK_DISTANCE`` away along w from the scene's
    centre, of angular radius alpha = ``ANGULAR_RADIUS``; a disk of radiance
    L and angular radius alpha gives E = L pi sin^2(alpha) head-on, so
    L = E / (pi sin^2 alpha). Its light arrives within alpha of w: a cosine
    moves by at most alpha (5 %), by alpha^2 / 4 on average over the disk.
  - its emitters are black (they absorb what reaches them) and hidden from
    the camera, as in all three renders (``hide_emitters``): the measured
    pixels see diffuse surfaces, never an emitter.

The course's rough material is the Blinn-Phong ``kd + ks (n.h)^s /
cos theta_i``, which is not reciprocal (its ``1 / cos theta_i`` belongs to
the light's side): a light tracer evaluates it with the directions swapped
and would measure another material. For the measurement every
``course_rough`` becomes a ``lambert`` of albedo ``diffuse`` (the course's
diffuse colour, at most 0.8 in the course scenes); the measured scene, with
that substitution and its render settings, is written whole into the
reference (``scene_text``), so the harness renders exactly what Mitsuba saw.

The measured scene's background is black: the light measured is the delta
lights' light. A background is an area light at infinity, which a path
tracer's sampled bounces find through any chain of delta surfaces, so it is
not what goes missing; and Mitsuba's light tracer emits it from a disk as
wide as the scene's bounds, which the course's planes (disks of 10^6 m)
make so wide that almost no light path reaches the camera (on
``glass_spheres`` it found 0.35 of what the path tracer finds).

Two regions are measured: ``diffuse``, the pixels whose centre and eight
neighbours' centres all see a diffuse surface first (so the box footprint
does too, but for sub-pixel features), where all three estimates apply; and
``surface``, the pixels that so see any surface, where the light tracer
does not (it misses what the camera sees through a delta surface). Per pass
the reference keeps each region's mean radiance per channel (an empty list
where the region has no pixel); per pixel the mean over the passes.
Russian roulette is off (``rr_depth`` past ``max_depth``).

Mitsuba's light tracer splats into the film from every thread in an order
that varies; it runs on one thread (``dr.set_thread_count(1)``) so the file
is byte-for-byte stable. The path tracer's blocks are seeded by position
and do not depend on the threads.
"""
import json
import math
import os
import sys

import drjit as dr
import mitsuba as mi
import numpy as np

import mitsuba_render as mr
from atomic_write import write_text

ROOT = mr.ROOT
DEFAULT_PATH = os.path.join(ROOT, "validation", "reference", "mitsuba_full_light.json")
REGENERATE = ".venv/bin/python python-checks/mitsuba_full_light.py"
SCHEMA = "mitsuba-full-light/1"

WIDTH, HEIGHT = 80, 60
# Independent passes: the standard error of a region's mean comes from
# their spread (Student t with PASSES - 1 degrees of freedom).
PASSES = 16
SPP = 64
# Bounces after the primary hit, the suite's count (Mitsuba's is + 2).
MAX_DEPTH = 16
# The area lights' angular radius, radians (see the module doc).
ANGULAR_RADIUS = 0.05
DISK_DISTANCE = 1.0e4

# The course scenes not measured, and why not; every other course scene
# (``mr.course_scenes``, in its order) is measured.
EXCLUDED = {
    "first_red_sphere": "no light: an emitter alone, nothing to miss",
    "normals": "shows the normal as a colour: not a radiance",
    "kaleidoscope": "its only light cannot enter the closed mirror tube: every estimate is black",
}
SCENES = [name for name in mr.course_scenes() if name not in EXCLUDED]
# The regions measured, by what the camera sees first: a diffuse surface
# (where all three estimates apply), any surface (the light tracer cannot
# see through a delta surface, so only ``path`` and ``area`` there).
REGIONS = {
    "diffuse": lambda kind: kind == "lambert",
    "surface": lambda kind: kind is not None,
}
ESTIMATES = ("path", "ptracer", "area", "path_centres")
# Samples per pixel of each pass of ``path_centres`` (one ray at a time from
# Python, so fewer).
CENTRE_SPP = 16


def measured_scene(scene):
    """The scene as measured: course_rough as Lambert, the path settings,
    the background black."""
    out = json.loads(json.dumps(scene))
    for name, material in out["materials"].items():
        if material["type"] == "course_rough":
            out["materials"][name] = {"type": "lambert", "albedo": material["diffuse"]}
    out["image"] = {"width": WIDTH, "height": HEIGHT}
    out["render"] = {"integrator": "path", "max_depth": MAX_DEPTH, "throughput_cutoff": 0}
    out["background"] = [0, 0, 0]
    return out


def distance_to_surfaces(scene, p):
    """The distance from p to the nearest object's surface."""
    best = math.inf
    for obj in scene["objects"]:
        if obj["type"] == "sphere":
            offset = [a - b for a, b in zip(p, obj["center"])]
            best = min(best, abs(math.sqrt(mr.dot(offset, offset)) - obj["radius"]))
        elif obj["type"] == "plane":
            n = mr.normalize(obj["normal"])
            best = min(best, abs(mr.dot(n, [a - b for a, b in zip(p, obj["point"])])))
        elif obj["type"] == "mirror_tube":
            axis = mr.normalize(obj["axis"])
            offset = [a - b for a, b in zip(p, obj["axis_point"])]
            along = mr.dot(offset, axis)
            radial = math.sqrt(max(mr.dot(offset, offset) - along * along, 0.0))
            # The inscribed circle of the polygon: a lower bound on the distance to a strip.
            inner = obj["radius"] * math.cos(math.pi / obj["sides"])
            best = min(best, abs(inner - radial))
        else:
            raise mr.SceneError(f"objects: unknown object {obj['type']!r}")
    return best


def scene_centre(scene):
    points = [o["center"] for o in scene["objects"] if o["type"] == "sphere"]
    if not points:
        return [0.0, 0.0, 0.0]
    return [sum(p[i] for p in points) / len(points) for i in range(3)]


def area_lights(scene):
    """The Mitsuba shapes that replace the scene's delta lights, and a
    description of each."""
    shapes, described = {}, []
    black = {"type": "diffuse", "reflectance": mr.rgb([0, 0, 0])}
    for i, light in enumerate(scene.get("lights", [])):
        if light["type"] == "point":
            p = light["position"]
            r = ANGULAR_RADIUS * distance_to_surfaces(scene, p)
            radiance = [c / (math.pi * r * r) for c in light["intensity"]]
            shapes[f"light{i}"] = {"type": "sphere", "center": p, "radius": r, "bsdf": black,
                                   "emitter": {"type": "area", "radiance": mr.rgb(radiance)}}
            described.append({"light": i, "type": "sphere", "radius": r, "radiance": radiance})
        elif light["type"] == "directional":
            w = mr.normalize(light["towards"])
            centre = [c + DISK_DISTANCE * d for c, d in zip(scene_centre(scene), w)]
            radius = DISK_DISTANCE * math.tan(ANGULAR_RADIUS)
            radiance = [c / (math.pi * math.sin(ANGULAR_RADIUS) ** 2) for c in light["irradiance"]]
            # A disk emits along its local +z: facing the scene, -w.
            facing = [-c for c in w]
            u = mr.any_perpendicular(facing)
            v = mr.cross(facing, u)
            to_world = mr.frame_matrix([c * radius for c in u], [c * radius for c in v], facing, centre)
            shapes[f"light{i}"] = {"type": "disk", "to_world": to_world, "bsdf": black,
                                   "emitter": {"type": "area", "radiance": mr.rgb(radiance)}}
            described.append({"light": i, "type": "disk", "distance": DISK_DISTANCE, "radius": radius,
                              "radiance": radiance})
        else:
            raise mr.SceneError(f"lights[{i}].type: unknown light {light['type']!r}")
    return shapes, described


def mitsuba_dict(scene, estimate):
    """The Mitsuba scene of one estimate."""
    out = mr.mitsuba_scene(scene, WIDTH, HEIGHT, MAX_DEPTH)
    out["sensor"]["film"]["rfilter"] = {"type": "box"}
    out["sensor"]["sampler"] = {"type": "independent", "sample_count": SPP}
    kind = "ptracer" if estimate == "ptracer" else "path"  # path_centres: path, at the centres
    out["integrator"] = {"type": kind, "max_depth": MAX_DEPTH + 2, "rr_depth": MAX_DEPTH + 3,
                         "hide_emitters": True}
    if estimate == "area":
        for i in range(len(scene.get("lights", []))):
            del out[f"light{i}"]
        out.update(area_lights(scene)[0])
    return out


def regions(scene, mitsuba):
    """Per region, 1 where the pixel's centre and its eight neighbours'
    centres all see a surface of the region's kind first."""
    sensor = mitsuba.sensors()[0]
    kinds = [scene["materials"][o["material"]]["type"] for o in scene["objects"]]
    first = []
    for y in range(HEIGHT):
        for x in range(WIDTH):
            si = mitsuba.ray_intersect(mr.pixel_ray(sensor, x, y, WIDTH, HEIGHT))
            first.append(kinds[mr.object_index(si.shape)] if si.is_valid() else None)
    out = {}
    for region, wanted in REGIONS.items():
        mask = []
        for y in range(HEIGHT):
            for x in range(WIDTH):
                inside = 0 < x < WIDTH - 1 and 0 < y < HEIGHT - 1
                mask.append(1 if inside and all(wanted(first[j * WIDTH + i]) for j in range(y - 1, y + 2)
                                                for i in range(x - 1, x + 2)) else 0)
        out[region] = mask
    return out


def render_passes(mitsuba, estimate):
    """The images of the passes, each ``height x width x 3``."""
    if estimate == "path_centres":
        return [centre_pass(mitsuba, seed) for seed in range(PASSES)]
    threads = dr.thread_count()
    if estimate == "ptracer":
        dr.set_thread_count(1)
    try:
        return [np.array(mi.render(mitsuba, spp=SPP, seed=seed), dtype=np.float64) for seed in range(PASSES)]
    finally:
        dr.set_thread_count(threads)


def centre_pass(mitsuba, seed):
    """One pass of Mitsuba's path integrator through the pixel centres, as
    the suite's tracer samples them (``mitsuba_render.pixel_ray``): the
    film's box filter averages over the pixel instead, which moves a
    region's mean where the image has detail within a pixel."""
    sensor, integrator = mitsuba.sensors()[0], mitsuba.integrator()
    sampler = mi.load_dict({"type": "independent"})
    image = np.zeros((HEIGHT, WIDTH, 3))
    for y in range(HEIGHT):
        for x in range(WIDTH):
            ray = mr.pixel_ray(sensor, x, y, WIDTH, HEIGHT)
            sampler.seed((seed * HEIGHT + y) * WIDTH + x)
            total = [0.0, 0.0, 0.0]
            for _ in range(CENTRE_SPP):
                value, _, _ = integrator.sample(mitsuba, sampler, mi.RayDifferential3f(ray))
                total = [t + float(value[c]) for c, t in enumerate(total)]
                sampler.advance()
            image[y, x] = [t / CENTRE_SPP for t in total]
    return image


def render_estimate(scene, estimate, masks):
    """Per pass each region's mean per channel; per pixel the mean over passes."""
    mitsuba = mi.load_dict(mitsuba_dict(scene, estimate), optimize=False)
    images = render_passes(mitsuba, estimate)
    passes = {}
    for region, mask in masks.items():
        inside = np.array(mask, dtype=bool).reshape(HEIGHT, WIDTH)
        passes[region] = [[float(v) for v in image[inside].mean(axis=0)] if inside.any() else []
                          for image in images]
    mean = np.mean(images, axis=0).reshape(-1)
    return {"mean_f32le": mr.f32_base64([float(v) for v in mean]), "passes_region_mean": passes}


def render_scene(name):
    relative = f"crates/tracer/scenes/{name}.json"
    with open(os.path.join(ROOT, relative), encoding="utf-8") as f:
        scene = measured_scene(json.load(f))
    masks = regions(scene, mi.load_dict(mitsuba_dict(scene, "path"), optimize=False))
    entry = {
        "name": name,
        "scene_file": relative,
        "scene_text": json.dumps(scene, indent=2) + "\n",
        "width": WIDTH,
        "height": HEIGHT,
        "area_lights": area_lights(scene)[1],
        "regions": {region: {"pixels": sum(mask), "mask_u8": mr.u8_base64(mask)} for region, mask in masks.items()},
    }
    for estimate in ESTIMATES:
        entry[estimate] = render_estimate(scene, estimate, masks)
    return entry


def build(scenes=SCENES):
    mi.set_log_level(mi.LogLevel.Warn)
    return {
        "schema": SCHEMA,
        "generator": "python-checks/mitsuba_full_light.py",
        "regenerate": REGENERATE,
        "description": (
            f"All the light of the course scenes at {WIDTH}x{HEIGHT} (course_rough as Lambert), by Mitsuba "
            f"{mi.__version__} ({mr.VARIANT}): its path integrator with the delta lights (what it misses), its "
            "light tracer (ptracer) and its path integrator with each delta light as an area light of equal "
            f"power; {PASSES} passes of {SPP} samples per pixel each, box filter, Russian roulette off"
        ),
        "mitsuba": {"version": mi.__version__, "variant": mr.VARIANT},
        "passes": PASSES,
        "spp": SPP,
        "centre_spp": CENTRE_SPP,
        "max_depth": MAX_DEPTH,
        "angular_radius": ANGULAR_RADIUS,
        "excluded": EXCLUDED,
        "scenes": [render_scene(name) for name in scenes],
    }


def deeper(name, spp):
    """Prints the ``diffuse`` region's mean (R + G + B) and standard error of
    the light tracer and the area lights at ``spp`` samples per pixel and
    pass: the independent check's two sides with more power than the
    reference's, written nowhere."""
    global SPP
    mi.set_log_level(mi.LogLevel.Warn)
    with open(os.path.join(ROOT, f"crates/tracer/scenes/{name}.json"), encoding="utf-8") as f:
        scene = measured_scene(json.load(f))
    masks = regions(scene, mi.load_dict(mitsuba_dict(scene, "path"), optimize=False))
    SPP = spp
    for estimate in ("ptracer", "area"):
        values = [sum(p) for p in render_estimate(scene, estimate, masks)["passes_region_mean"]["diffuse"]]
        mean = sum(values) / len(values)
        se = math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1) / len(values))
        print(f"{name} {estimate} {spp} spp x {PASSES} passes: {mean:.6f} +- {se:.6f}")


def main(argv):
    if len(argv) == 4 and argv[1] == "--deeper":
        deeper(argv[2], int(argv[3]))
        return 0
    path = argv[1] if len(argv) > 1 else DEFAULT_PATH
    try:
        document = build()
    except mr.SceneError as error:
        print(f"mitsuba_full_light.py: {error}", file=sys.stderr)
        return 1
    mr.write(document, path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
