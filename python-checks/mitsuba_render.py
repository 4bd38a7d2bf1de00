"""The course scenes rendered by Mitsuba 3: a Whitted integrator written on
Mitsuba's own primitives, and Mitsuba's ``path`` integrator.

Regenerate (from the repository root; the output is byte-for-byte stable):

    .venv/bin/python python-checks/mitsuba_render.py

writes ``validation/reference/mitsuba_renders.json`` (schema
``mitsuba-renders/2``, described in ``validation/README.md``). It takes about
two and a half minutes on a 2-core machine (Mitsuba's ``scalar_rgb`` variant:
the Whitted renders one ray at a time from Python, the path renders through
``mi.render``, two scenes at a time).

The scenes are the tracer's course list (``scene_list.py``, which reads
``crates/tracer/src/scene/shipped.json``): a scene added there gets its
references here, compared by both integrators unless
a material of it is not a radiance (``NOT_A_RADIANCE``) or it is listed in
``PATH_SKIPPED``.

One scene, one place: each Mitsuba scene is built here from the suite's own
scene file in ``crates/tracer/scenes/``, whose text the reference embeds, so the
harness renders exactly the scene Mitsuba saw and refuses a stale reference.

How the suite's scene maps to Mitsuba's (each checked by the render
comparison itself, and by ``test_mitsuba_render.py``):

- ``course_pinhole``: eye at (0, 0, -2) looking along +z, the image plane
  z = 0 spanning y in [-1, 1], so a ``perspective`` sensor with
  ``fov_axis = "y"`` and ``fov = 2 atan(1/2)``. The course's camera keeps +x on
  the right while looking along +z with +y up: a left-handed view. Mitsuba's
  ``look_at`` builds a right-handed one (its camera's x axis is
  ``cross(up, dir)``, which points to the image's left), so the course's
  camera is Mitsuba's ``look_at`` followed by a mirror of camera x.
- ``look_at``: the OpenGL view of ``002`` is right-handed, Mitsuba's too; the
  same ``eye``, ``target``, ``up``, ``fov_y_deg`` (``fov_axis = "y"``) and
  ``near``/``far`` clip planes, no mirror.
- The Whitted rays pass through pixel centres, as the suite's Whitted
  integrator's (``pixel_filter: "center"``): they come from the sensor's own
  ``sample_ray`` at position ``((x + 0.5) / w, (y + 0.5) / h)``. The path
  renders are Mitsuba's film's, box filtered (below).
- ``directional`` light: ``towards`` is the direction to the light, Mitsuba's
  ``direction`` the one the light travels, so its negative; the suite's
  ``irradiance`` (W/m^2 on a surface facing the light) is Mitsuba's
  ``irradiance``.
- ``point`` light: ``intensity`` in W/sr is Mitsuba's ``intensity``.
- ``background``: the radiance of escaping rays, Mitsuba's ``constant``
  emitter (which also lights the scene in the path tracer, as the suite's
  background does).
- ``conductor``: Mitsuba's smooth ``conductor`` with ``eta`` = n and ``k`` =
  kappa per channel, made ``twosided`` (the kaleidoscope's strips are seen from
  inside).
- ``course_rough``: the course's Blinn-Phong BRDF ``kd + ks (cos+ delta)^s /
  cos theta_i`` (1/sr, delta from the half vector) has no Mitsuba plugin; it is
  registered here as a two-sided Python BSDF, ``CourseBlinnPhong``, sampled by
  the cosine. Its ``ka L_ambient`` term exists only in the Whitted model.
- ``lambert``: Mitsuba's ``diffuse`` with ``reflectance`` = albedo, two-sided.
- ``flat``: an ``area`` emitter of that radiance on a black ``diffuse``
  surface: it emits and reflects nothing.
- ``plane``: Mitsuba has no infinite plane; a ``disk`` of radius
  ``PLANE_RADIUS`` = 10^6 m centred on ``point`` (the horizon moves by under
  10^-5 rad, on the silhouette the comparison masks). Where light bounces
  between two planes a finite disk lets the sky in past the other's rim: a
  Lambert floor meeting a Lambert wall under a uniform sky, whose radiance
  has a closed form, comes out 7.9e-4 to 9.0e-4 too bright on the wall
  with 10^4 m disks (5.0 to 6.8 standard errors) and within 5 standard
  errors of it with 10^6 m (``test_plane_stand_in.py``). Either is below
  what the path comparison resolves, which needs a difference beyond the
  Whitted tolerance, 1e-3 of the radiance. The disk's intersection is analytic
  (its size does not cost precision); a ``rectangle`` is two triangles,
  whose hit points lose precision in proportion to their size.
- ``mirror_tube``: each strip as 1 m ``rectangle`` pieces over 100 m either
  side of ``axis_point``, the corners placed as
  ``tracer::geometry::Tube`` places them. A ray that runs past the pieces
  escapes to the background in Mitsuba and bounces on to the depth limit
  (black) in the tracer: the same where the background is black, as in both
  kaleidoscopes, whose objects all lie within 20 m of the axis point.

The Whitted integrator (``whitted``) follows the suite's model
(``crates/tracer/src/integrator.rs``, ``docs/scene-schema.md``) using only
Mitsuba's machinery for the geometry and the optics: ``scene.ray_intersect``
and ``ray_test`` for hits and shadows (secondary rays offset as ``spawn``
explains), ``mi.fresnel_conductor``, ``mi.fresnel``,
``mi.reflect``, ``mi.refract``. The course's Blinn-Phong BRDF and the
irradiance of the two lights are the textbook definitions, written here
from ``003`` independently of the radiometry crate.

Monte Carlo: Mitsuba's ``path`` integrator through Mitsuba's own renderer,
``mi.render`` on the scene at ``PATH_WIDTH`` x ``PATH_HEIGHT``, its film's
reconstruction filter the ``box`` (radius half a pixel: each sample is
jittered over its pixel and counts in that pixel only, the suite's
``pixel_filter: "box"``), ``PATH_SAMPLES`` independent passes of one sample
per pixel with seeds 0, 1, ..., the per-pixel mean and the unbiased sample
variance of one sample (Welford's, in float64). Each scene renders in its own
process on one Mitsuba thread; the image does not depend on the thread count
(each image block draws from a stream of its own). Mitsuba's ``max_depth``
counts the segments of a path (1: emitters seen directly, 2: direct light);
the suite's counts bounces after the primary hit and adds the direct light at
the last vertex, so the suite's ``max_depth`` D is Mitsuba's D + 2. For the
delta lights exactly; not for light that leaves the last vertex by a sampled
direction and escapes (the background, through a mirror or glass, or off a
rough surface), which Mitsuba at D + 2 counts and the suite at D does not:
Mitsuba lets light escape after D + 1 scatterings, the suite after D
(``test_bench_vs_mitsuba.py``, a mirror under the sky). That last
scattering's light is negligible at 16 bounces, except where Mitsuba's
offsets free light at every bounce (inside a dielectric sphere, below).

Mitsuba's path integrator starts its secondary rays ``RayEpsilon (1 + max
|p_i|)`` off the surface (see ``spawn``); the suite's tracer much closer. Where
a pixel's light comes through a chain of mirrors onto a sharp highlight, that
alone moves the pixel. Its size is measured per pixel, as the difference of
the Whitted render with Mitsuba's ``si.spawn_ray`` and with ``spawn``
(``offset_sensitivity``); the harness allows a path mean to differ by that
much and reports it as a finding about the reference.

Images are little-endian, rows top to bottom, RGB interleaved, in base64:
the Whitted images float32 (``*_f32le``); the path statistics, 320 x 240,
zlib-compressed: the mean and the offset sensitivity as IEEE float16
(``*_f16le_zlib``: 11 significant bits, within 2.4e-4 relative, a quarter of
the deterministic pixels' tolerance and far below the statistical error of
64 samples; a value beyond its range, 65504, is refused), the standard
deviation of one sample as bfloat16 (``*_bf16le_zlib``: float32's range,
which a firefly's standard deviation needs, and 8 significant bits, within
2e-3 relative, against the 18 % statistical error of a standard deviation
from 64 samples). The edge mask is one byte per pixel (1: masked). A pixel
is an edge when one of its eight neighbours follows a different Whitted
path: another object at any vertex of the specular chain, or another light
blocked at a rough vertex.
"""
import argparse
import base64
import json
import math
import multiprocessing
import os
import struct
import sys
import zlib

import drjit as dr  # Mitsuba's array library, imported first
import mitsuba as mi
import numpy as np
from atomic_write import write_text
from scene_list import course_scenes

VARIANT = "scalar_rgb"
mi.set_variant(VARIANT)
# One Mitsuba thread: the path renders run the Python BSDF, which holds the
# GIL; more threads only contend for it (``WORKERS`` processes instead).
dr.set_thread_count(1)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_PATH = os.path.join(ROOT, "validation", "reference", "mitsuba_renders.json")
REGENERATE = ".venv/bin/python python-checks/mitsuba_render.py"
SCHEMA = "mitsuba-renders/2"

# The Whitted comparison's size: pixel centres, one Python call per pixel.
WIDTH, HEIGHT = 64, 48
# The path comparison's size: Mitsuba's own renderer (``mi.render``), box
# filtered. Five times the Whitted size each way, so each path pixel lies
# inside one Whitted pixel (``offset_sensitivity``).
PATH_WIDTH, PATH_HEIGHT = 320, 240
# Independent passes of ``mi.render`` at one sample per pixel, seeds 0, 1,
# ...: a per-pixel mean and an unbiased per-sample variance with 63 degrees
# of freedom. About two minutes of one core for the seven scenes
# (kaleidoscope_lit 1.2 s a pass, webgl_seven_spheres 0.7 s).
PATH_SAMPLES = 64
# Worker processes, one scene each (Mitsuba's threads run the Python BSDF
# under the GIL, so processes, each rendering on one thread, go faster).
WORKERS = 2
# Beyond everything a scene holds (the planes' disks reach 10^6 m): the
# film's rays end no sooner than the tracer's.
PATH_FAR_CLIP = 1.0e7
# Bounces of the path tracer after the primary hit (the suite's count). The
# two sides truncate differently only at the last vertex (the background is
# reached from there by Mitsuba's sampling, not by the suite's: the module
# doc), which 16 bounces make negligible.
PATH_MAX_DEPTH = 16
# Measured against a closed form (see the module doc, ``test_plane_stand_in.py``).
PLANE_RADIUS = 1.0e6
TUBE_HALF_LENGTH = 100.0
# Mitsuba's rectangle is two triangles, whose hit points lose precision in
# proportion to the triangle's size; 1 m pieces keep them within a few ε₃₂.
TUBE_SEGMENT_HALF_LENGTH = 0.5
# Secondary rays start this far (relative to the hit's largest coordinate)
# off the surface: 4 float32 ulps of that coordinate, clear of the hit
# point's rounding (see `spawn`).
SPAWN_OFFSET = 2.0 ** -21

# The scenes: the tracer's one course list (``course_scenes``), so a scene
# added there gets its references here. A scene with a material that is not
# a radiance is not compared (``excluded``); one listed in ``PATH_SKIPPED``
# is compared by Whitted only.
NOT_A_RADIANCE = {
    "normal_colour": "shows the normal as a colour: not a radiance, nothing to compare",
}
PATH_SKIPPED = {
    "kaleidoscope": "the directional light cannot enter the closed mirror tube: without the ambient term the path render is black everywhere, a comparison that could not fail",
}

# The schema's defaults (docs/scene-schema.md).
DEFAULT_MAX_DEPTH = 11
DEFAULT_CUTOFF = 1e-3


class SceneError(ValueError):
    """A scene this generator cannot express in Mitsuba, naming the field."""


def normalize(v):
    length = math.sqrt(sum(c * c for c in v))
    if not length > 0.0:
        raise SceneError(f"zero-length direction {v}")
    return [c / length for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def frame_matrix(x, y, z, origin):
    """A 4x4 transform whose columns are x, y, z and origin."""
    return mi.ScalarTransform4f(
        [[x[i], y[i], z[i], origin[i]] for i in range(3)] + [[0, 0, 0, 1]]
    )


def any_perpendicular(n):
    reference = [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0]
    return normalize(cross(n, reference))


class CourseBlinnPhong(mi.BSDF):
    """The course's Blinn-Phong BRDF, ``kd + ks (n.h)^s / cos theta_i`` per
    channel (1/sr), zero unless both directions are on one side; two-sided,
    sampled by the cosine. Mitsuba's ``si.wi`` is the direction to the viewer
    and the BSDF's ``wo`` the one to the light."""

    def __init__(self, props):
        mi.BSDF.__init__(self, props)
        self.kd = [props["kd_r"], props["kd_g"], props["kd_b"]]
        self.ks = [props["ks_r"], props["ks_g"], props["ks_b"]]
        self.shine = props["shininess"]
        flags = mi.BSDFFlags.DiffuseReflection | mi.BSDFFlags.FrontSide | mi.BSDFFlags.BackSide
        self.m_flags = flags
        self.m_components = [flags]

    def _f_cos(self, wi, wo):
        """``f_r cos theta`` toward ``wo``, in the frame flipped to the viewer."""
        sign = 1.0 if wi.z >= 0.0 else -1.0
        cos_v, cos_l = wi.z * sign, wo.z * sign
        if not (cos_v > 0.0 and cos_l > 0.0):
            return mi.Color3f(0.0)
        h = dr.normalize(wi + wo)
        cos_h = max(h.z * sign, 0.0)
        lobe = cos_h ** self.shine
        return mi.Color3f([self.kd[c] * cos_l + self.ks[c] * lobe for c in range(3)])

    def _pdf(self, wi, wo):
        sign = 1.0 if wi.z >= 0.0 else -1.0
        return max(wo.z * sign, 0.0) / math.pi

    def sample(self, ctx, si, sample1, sample2, active=True):
        bs = mi.BSDFSample3f()
        wo = mi.warp.square_to_cosine_hemisphere(sample2)
        if si.wi.z < 0.0:
            wo = mi.Vector3f(wo.x, wo.y, -wo.z)
        bs.wo = wo
        bs.pdf = self._pdf(si.wi, wo)
        bs.eta = 1.0
        bs.sampled_type = int(mi.BSDFFlags.DiffuseReflection)
        bs.sampled_component = 0
        if not bs.pdf > 0.0:
            return bs, mi.Color3f(0.0)
        return bs, self._f_cos(si.wi, wo) / bs.pdf

    def eval(self, ctx, si, wo, active=True):
        return self._f_cos(si.wi, wo)

    def pdf(self, ctx, si, wo, active=True):
        return self._pdf(si.wi, wo)

    def eval_pdf(self, ctx, si, wo, active=True):
        return self._f_cos(si.wi, wo), self._pdf(si.wi, wo)

    def to_string(self):
        return f"CourseBlinnPhong[kd={self.kd}, ks={self.ks}, shininess={self.shine}]"


mi.register_bsdf("course_blinn_phong", lambda props: CourseBlinnPhong(props))


def rgb(value):
    return {"type": "rgb", "value": [float(c) for c in value]}


def mitsuba_bsdf(name, material):
    kind = material.get("type")
    if kind == "course_rough":
        d, s = material["diffuse"], material["specular"]
        return {
            "type": "course_blinn_phong",
            "kd_r": float(d[0]), "kd_g": float(d[1]), "kd_b": float(d[2]),
            "ks_r": float(s[0]), "ks_g": float(s[1]), "ks_b": float(s[2]),
            "shininess": float(material["shininess"]),
        }
    if kind == "lambert":
        return {"type": "twosided", "bsdf": {"type": "diffuse", "reflectance": rgb(material["albedo"])}}
    if kind == "conductor":
        return {"type": "twosided", "bsdf": {"type": "conductor", "eta": rgb(material["n"]), "k": rgb(material["kappa"])}}
    if kind == "dielectric":
        return {"type": "dielectric", "int_ior": float(material["eta"]), "ext_ior": 1.0}
    if kind == "flat":
        return {"type": "diffuse", "reflectance": rgb([0, 0, 0])}
    raise SceneError(f"materials.{name}.type: {kind!r} has no physical counterpart in Mitsuba")


def mitsuba_sensor(camera, width, height):
    kind = camera.get("type")
    film = {"type": "hdrfilm", "width": width, "height": height, "pixel_format": "rgb"}
    if kind == "course_pinhole":
        to_world = mi.ScalarTransform4f().look_at(origin=[0, 0, -2], target=[0, 0, 0], up=[0, 1, 0])
        # Mitsuba's camera x points to the image's left; the course's to its right.
        to_world = to_world @ mi.ScalarTransform4f().scale([-1, 1, 1])
        return {"type": "perspective", "fov_axis": "y", "fov": math.degrees(2 * math.atan(0.5)),
                "near_clip": 1e-3, "far_clip": 1e5, "to_world": to_world, "film": film}
    if kind == "look_at":
        to_world = mi.ScalarTransform4f().look_at(origin=camera["eye"], target=camera["target"], up=camera["up"])
        return {"type": "perspective", "fov_axis": "y", "fov": float(camera["fov_y_deg"]),
                "near_clip": float(camera["near"]), "far_clip": float(camera["far"]),
                "to_world": to_world, "film": film}
    raise SceneError(f"camera.type: unknown camera {kind!r}")


def mitsuba_scene(scene, width, height, path_max_depth):
    """The Mitsuba scene dictionary of one of the suite's scenes."""
    out = {"type": "scene",
           "sensor": mitsuba_sensor(scene["camera"], width, height),
           "integrator": {"type": "path", "max_depth": path_max_depth + 2, "hide_emitters": False}}
    materials = scene["materials"]
    for i, obj in enumerate(scene["objects"]):
        name = obj["material"]
        if name not in materials:
            raise SceneError(f"objects[{i}].material: no material named {name!r}")
        material = materials[name]
        bsdf = mitsuba_bsdf(name, material)
        kind = obj["type"]
        if kind == "sphere":
            shape = {"type": "sphere", "center": obj["center"], "radius": float(obj["radius"]), "bsdf": bsdf}
            if material["type"] == "flat":
                shape["emitter"] = {"type": "area", "radiance": rgb(material["radiance"])}
            out[f"obj{i}"] = shape
        elif kind == "plane":
            n = normalize(obj["normal"])
            u = any_perpendicular(n)
            v = cross(n, u)
            s = PLANE_RADIUS
            shape = {"type": "disk", "bsdf": bsdf,
                     "to_world": frame_matrix([c * s for c in u], [c * s for c in v], n, obj["point"])}
            if material["type"] == "flat":
                shape["emitter"] = {"type": "area", "radiance": rgb(material["radiance"])}
            out[f"obj{i}"] = shape
        elif kind == "mirror_tube":
            axis = normalize(obj["axis"])
            reference = [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 1.0, 0.0]
            u = normalize([r - a * dot(reference, axis) for r, a in zip(reference, axis)])
            v = cross(axis, u)
            sides, radius, p0 = obj["sides"], obj["radius"], obj["axis_point"]

            def corner(k):
                a = 2 * math.pi * k / sides
                return [p0[j] + (u[j] * math.cos(a) + v[j] * math.sin(a)) * radius for j in range(3)]

            segments = round(TUBE_HALF_LENGTH / TUBE_SEGMENT_HALF_LENGTH)
            for k in range(sides):
                p1, p2 = corner(k), corner(k + 1)
                half = [(b - a) / 2 for a, b in zip(p1, p2)]
                mid = [(a + b) / 2 for a, b in zip(p1, p2)]
                outward = normalize(cross(half, axis))
                along = [c * TUBE_SEGMENT_HALF_LENGTH for c in axis]
                for j in range(-segments, segments):
                    centre = [m + a * (2 * j + 1) for m, a in zip(mid, along)]
                    out[f"obj{i}_side{k}_part{j + segments}"] = {
                        "type": "rectangle", "bsdf": bsdf,
                        "to_world": frame_matrix(half, along, outward, centre)}
        else:
            raise SceneError(f"objects[{i}].type: unknown object {kind!r}")
    for i, light in enumerate(scene.get("lights", [])):
        if light["type"] == "directional":
            towards = normalize(light["towards"])
            out[f"light{i}"] = {"type": "directional", "direction": [-c for c in towards],
                                "irradiance": rgb(light["irradiance"])}
        elif light["type"] == "point":
            out[f"light{i}"] = {"type": "point", "position": light["position"],
                                "intensity": rgb(light["intensity"])}
        else:
            raise SceneError(f"lights[{i}].type: unknown light {light['type']!r}")
    background = scene.get("background", [0, 0, 0])
    if any(c > 0 for c in background):
        out["background"] = {"type": "constant", "radiance": rgb(background)}
    return out


def object_index(shape):
    """The suite's object index of a Mitsuba shape, from its id ``obj{i}[_side{k}]``."""
    return int(shape.id()[3:].split("_")[0])


def spawn(si, direction):
    """A ray leaving the hit ``si`` along ``direction``, its origin moved off
    the surface by ``SPAWN_OFFSET (1 + max |p_i|)`` along the normal on the
    side it leaves by. Mitsuba's own ``si.spawn_ray`` moves it by
    ``RayEpsilon (1 + max |p_i|)``, ``mi.math.RayEpsilon`` = 1500 * 2^-24
    (about 8.9e-5): on the kaleidoscope's chains of four or five mirrors that
    shifts the final hit by a fraction of a millimetre and the course's
    s = 100 highlight there by up to 5 %, a difference of offsets, not of the
    laws compared. With this offset the
    same pixel agrees with an exact float64 trace to 3e-6."""
    n = si.n if dr.dot(si.n, direction) >= 0.0 else -si.n
    scale = 1.0 + max(abs(si.p.x), abs(si.p.y), abs(si.p.z))
    return mi.Ray3f(si.p + n * (SPAWN_OFFSET * scale), direction)


def spawn_to(si, target):
    """A shadow ray from ``si`` that stops just short of ``target``."""
    offset = target - si.p
    distance = dr.norm(offset)
    ray = spawn(si, offset / distance)
    ray.maxt = dr.norm(target - ray.o) * (1.0 - SPAWN_OFFSET)
    return ray


class Whitted:
    """The suite's Whitted model on Mitsuba's primitives (see the module doc)."""

    def __init__(self, scene, mitsuba, max_depth, cutoff, mitsuba_offsets=False):
        self.scene = scene
        # Mitsuba's own si.spawn_ray offsets instead of `spawn`'s: to measure
        # how much its path integrator's offsets move each pixel.
        self.spawn = (lambda si, d: si.spawn_ray(d)) if mitsuba_offsets else spawn
        self.spawn_to = (lambda si, p: si.spawn_ray_to(p)) if mitsuba_offsets else spawn_to
        self.mi_scene = mitsuba
        self.max_depth = max_depth
        self.cutoff = cutoff
        self.background = mi.Color3f(scene.get("background", [0, 0, 0]))
        self.ambient = mi.Color3f(scene.get("ambient", [0, 0, 0]))
        self.materials = [scene["materials"][o["material"]] for o in scene["objects"]]
        self.lights = scene.get("lights", [])

    def radiance(self, ray, depth, throughput, signature):
        """Radiance along ``ray``; appends what the path met to ``signature``."""
        si = self.mi_scene.ray_intersect(ray)
        if not si.is_valid():
            signature.append(-1)
            return self.background
        index = object_index(si.shape)
        signature.append(index)
        material = self.materials[index]
        kind = material["type"]
        if kind == "flat":
            return mi.Color3f(material["radiance"])
        if kind == "normal_colour":
            raise SceneError(f"objects[{index}]: normal_colour is not a radiance")
        wo = -ray.d
        n = si.n
        if kind in ("course_rough", "lambert"):
            if dr.dot(n, ray.d) > 0.0 and self.scene["objects"][index]["type"] != "sphere":
                n = -n  # two-sided planes are shaded on the viewer's side
            return self.ambient_term(material) + self.direct(si, n, wo, material, signature)
        if kind == "conductor":
            facing = -n if dr.dot(n, wo) < 0.0 else n
            cos_i = dr.dot(facing, wo)
            f = mi.Color3f([mi.fresnel_conductor(cos_i, mi.Complex2f(material["n"][c], material["kappa"][c]))
                            for c in range(3)])
            following = throughput * f
            if depth >= self.max_depth or max(following) < self.cutoff:
                return mi.Color3f(0.0)
            reflected = self.spawn(si, mi.reflect(wo, facing))
            return f * self.radiance(reflected, depth + 1, following, signature)
        if kind == "dielectric":
            if depth >= self.max_depth:
                return mi.Color3f(0.0)
            cos_o = dr.dot(n, wo)
            r, cos_t, eta_it, eta_ti = mi.fresnel(cos_o, material["eta"])
            total = mi.Color3f(0.0)
            if max(throughput) * r >= self.cutoff:
                reflected = self.spawn(si, mi.reflect(wo, n))
                total += r * self.radiance(reflected, depth + 1, throughput * r, signature)
            if cos_t != 0.0:
                # Radiance across the interface: L / n^2 is conserved, so
                # the refracted branch carries (1 - R) / eta_it^2, Mitsuba's
                # own eta_ti^2 (dielectric.cpp, `sample`, TransportMode::Radiance).
                weight = (1.0 - r) / (eta_it * eta_it)
                if max(throughput) * weight >= self.cutoff:
                    refracted = self.spawn(si, mi.refract(wo, n, cos_t, eta_ti))
                    total += weight * self.radiance(refracted, depth + 1, throughput * weight, signature)
            return total
        raise SceneError(f"objects[{index}]: unknown material type {kind!r}")

    def ambient_term(self, material):
        if material["type"] == "course_rough":
            return mi.Color3f(material["ambient"]) * self.ambient
        return mi.Color3f(material["albedo"]) * self.ambient

    def brdf(self, material, n, wi, wo):
        """The BRDF (1/sr) per channel, zero unless both directions are above."""
        cos_i, cos_o = dr.dot(n, wi), dr.dot(n, wo)
        if not (cos_i > 0.0 and cos_o > 0.0):
            return mi.Color3f(0.0)
        if material["type"] == "lambert":
            return mi.Color3f(material["albedo"]) / math.pi
        h = dr.normalize(wi + wo)
        lobe = max(dr.dot(n, h), 0.0) ** material["shininess"]
        return mi.Color3f([material["diffuse"][c] + material["specular"][c] * lobe / cos_i for c in range(3)])

    def direct(self, si, n, wo, material, signature):
        total = mi.Color3f(0.0)
        for light in self.lights:
            if light["type"] == "directional":
                wi = mi.Vector3f(normalize(light["towards"]))
                irradiance = mi.Color3f(light["irradiance"]) * max(dr.dot(n, wi), 0.0)
                shadow = self.spawn(si, wi)
            else:
                position = mi.Point3f(light["position"])
                offset = position - si.p
                r2 = dr.dot(offset, offset)
                wi = offset / math.sqrt(r2)
                irradiance = mi.Color3f(light["intensity"]) * (max(dr.dot(n, wi), 0.0) / r2)
                shadow = self.spawn_to(si, position)
            if not max(irradiance) > 0.0:
                signature.append(-2)
                continue
            f = self.brdf(material, n, wi, wo)
            if not max(f) > 0.0:
                signature.append(-2)
                continue
            if self.mi_scene.ray_test(shadow):
                signature.append(-3)
                continue
            signature.append(-4)
            total += f * irradiance
        return total


def pixel_ray(sensor, x, y, width, height):
    """The sensor's ray through the centre of pixel (x, y), unclipped: the
    suite's far plane only gives the direction of a ray, it does not end it."""
    ray, _ = sensor.sample_ray(0.0, 0.5, mi.Point2f((x + 0.5) / width, (y + 0.5) / height), mi.Point2f(0.5, 0.5))
    return mi.Ray3f(ray.o, ray.d)


def render_whitted(scene, mitsuba, width, height, mitsuba_offsets=False):
    """The Whitted image (row-major RGB list) and each pixel's path signature."""
    settings = scene.get("render", {})
    integrator = Whitted(scene, mitsuba, settings.get("max_depth", DEFAULT_MAX_DEPTH),
                         settings.get("throughput_cutoff", DEFAULT_CUTOFF), mitsuba_offsets)
    sensor = mitsuba.sensors()[0]
    image, signatures = [], []
    for y in range(height):
        for x in range(width):
            signature = []
            value = integrator.radiance(pixel_ray(sensor, x, y, width, height), 0, mi.Color3f(1.0), signature)
            image.extend(float(c) for c in value)
            signatures.append(tuple(signature))
    return image, signatures


def edge_mask(signatures, width, height):
    """1 where a neighbour (8-connected) follows a different path."""
    mask = []
    for y in range(height):
        for x in range(width):
            own = signatures[y * width + x]
            edge = any(
                signatures[j * width + i] != own
                for j in range(max(y - 1, 0), min(y + 2, height))
                for i in range(max(x - 1, 0), min(x + 2, width))
            )
            mask.append(1 if edge else 0)
    return mask


def path_scene(scene, width=PATH_WIDTH, height=PATH_HEIGHT, sampler="independent"):
    """The Mitsuba scene of the path comparison: ``PATH_WIDTH`` x
    ``PATH_HEIGHT``, a box-filtered film, an independent sampler (or the
    ``sampler`` named: ``bench_vs_mitsuba.py`` also times ``stratified``), and the
    sensor's rays unclipped at ``PATH_FAR_CLIP``: the suite's far plane only
    gives a ray's direction (``pixel_ray`` does the same for the Whitted
    rays), and Mitsuba's film would end the rays there (100 m on
    ``webgl_seven_spheres``, whose ground plane then stops short of the
    horizon)."""
    d = mitsuba_scene(scene, width, height, PATH_MAX_DEPTH)
    d["sensor"]["far_clip"] = PATH_FAR_CLIP
    d["sensor"]["film"]["rfilter"] = {"type": "box"}
    d["sensor"]["sampler"] = {"type": sampler, "sample_count": 1}
    return mi.load_dict(d, optimize=False)


def render_path(mitsuba, samples):
    """Per-pixel mean and unbiased variance of one sample of Mitsuba's path
    tracer (float64 arrays of shape (height, width, 3)): ``samples`` passes of
    ``mi.render`` at one sample per pixel, seeds 0 to ``samples - 1``."""
    mean = squares = None
    for seed in range(samples):
        image = np.array(mi.render(mitsuba, seed=seed, spp=1), dtype=np.float64)
        if mean is None:
            mean, squares = np.zeros_like(image), np.zeros_like(image)
        # Welford's running mean and sum of squared deviations: no
        # cancellation when every sample is the same.
        delta = image - mean
        mean += delta / (seed + 1)
        squares += delta * (image - mean)
    return mean, squares / (samples - 1)


def f16_zlib_base64(values, field):
    """``values`` as little-endian IEEE float16 (round to nearest even),
    zlib-compressed (level 9), base64. Refuses, naming ``field``, a value
    float16 cannot hold."""
    wide = np.asarray(values, dtype=np.float64).ravel()
    if not np.all(np.abs(wide) <= 65504.0):
        raise SceneError(f"{field}: {np.max(np.abs(wide)):.6g} is beyond float16")
    half = wide.astype("<f2")
    return base64.b64encode(zlib.compress(half.tobytes(), 9)).decode("ascii")


def bf16_zlib_base64(values):
    """``values`` as little-endian bfloat16 (float32's top 16 bits, rounded to
    nearest even), zlib-compressed (level 9), base64: float32's range, 8
    significant bits."""
    bits = np.asarray(values, dtype="<f4").ravel().view("<u4").astype(np.uint64)
    rounded = ((bits + 0x7FFF + ((bits >> 16) & 1)) >> 16).astype("<u2")
    return base64.b64encode(zlib.compress(rounded.tobytes(), 9)).decode("ascii")


def f32_base64(values):
    return base64.b64encode(struct.pack(f"<{len(values)}f", *values)).decode("ascii")


def u8_base64(values):
    return base64.b64encode(bytes(values)).decode("ascii")


def scene_text(name):
    relative = f"crates/tracer/scenes/{name}.json"
    with open(os.path.join(ROOT, relative), encoding="utf-8") as f:
        return relative, f.read()


def why_excluded(scene):
    """Why a scene is not compared at all, or None."""
    for material in scene["materials"].values():
        if material.get("type") in NOT_A_RADIANCE:
            return NOT_A_RADIANCE[material["type"]]
    return None


def upsampled_sensitivity(sensitivity, width, height):
    """The Whitted-size offset sensitivity (flat RGB list) at the path size:
    each path pixel lies inside one Whitted pixel (the sizes are a whole
    factor apart); it takes the largest of that pixel and its eight
    neighbours, since the Whitted value is known at their centres only."""
    small = np.asarray(sensitivity, dtype=np.float64).reshape(height, width, 3)
    padded = np.pad(small, ((1, 1), (1, 1), (0, 0)), mode="edge")
    neighbourhood = np.max([padded[j:j + height, i:i + width] for j in range(3) for i in range(3)], axis=0)
    factor = PATH_WIDTH // width
    return np.repeat(np.repeat(neighbourhood, factor, axis=0), factor, axis=1)


def render_scene(name, width=WIDTH, height=HEIGHT, samples=PATH_SAMPLES):
    relative, text = scene_text(name)
    scene = json.loads(text)
    path_too = name not in PATH_SKIPPED
    # optimize=False keeps every shape apart (Mitsuba merges meshes sharing a
    # BSDF otherwise), so a hit names the suite's object.
    mitsuba = mi.load_dict(mitsuba_scene(scene, width, height, PATH_MAX_DEPTH), optimize=False)
    image, signatures = render_whitted(scene, mitsuba, width, height)
    settings = scene.get("render", {})
    entry = {
        "name": name,
        "scene_file": relative,
        "scene_text": text,
        "width": width,
        "height": height,
        "whitted": {
            "max_depth": settings.get("max_depth", DEFAULT_MAX_DEPTH),
            "throughput_cutoff": settings.get("throughput_cutoff", DEFAULT_CUTOFF),
            "radiance_f32le": f32_base64(image),
        },
        "edges_u8": u8_base64(edge_mask(signatures, width, height)),
    }
    if path_too:
        mean, variance = render_path(path_scene(scene), samples)
        moved, _ = render_whitted(scene, mitsuba, width, height, mitsuba_offsets=True)
        sensitivity = upsampled_sensitivity([abs(a - b) for a, b in zip(moved, image)], width, height)
        entry["path"] = {
            "width": PATH_WIDTH,
            "height": PATH_HEIGHT,
            "pixel_filter": "box",
            "max_depth": PATH_MAX_DEPTH,
            "mitsuba_max_depth": PATH_MAX_DEPTH + 2,
            "samples": samples,
            "seeds": f"0 to {samples - 1}, one sample per pixel each",
            "mean_f16le_zlib": f16_zlib_base64(mean, f"{name}: path.mean"),
            "std_bf16le_zlib": bf16_zlib_base64(np.sqrt(variance)),
            "offset_sensitivity_f16le_zlib": f16_zlib_base64(sensitivity, f"{name}: path.offset_sensitivity"),
        }
    else:
        entry["path_skipped"] = PATH_SKIPPED[name]
    return entry


def build(only=None):
    """The whole document; with ``only``, the same document holding that one
    scene's entry (``select`` of the whole), which is what the proof of
    reproducibility regenerates from scratch on every CI run."""
    names = course_scenes()
    if only is not None and only not in names:
        raise SceneError(f"--only {only}: not a course scene (one of {', '.join(names)})")
    excluded, compared = {}, []
    for name in names:
        if only is not None and name != only:
            continue
        reason = why_excluded(json.loads(scene_text(name)[1]))
        if reason:
            excluded[name] = reason
        else:
            compared.append(name)
    # One process per scene at a time; the order of the entries is the list's.
    with multiprocessing.get_context("spawn").Pool(WORKERS) as pool:
        entries = pool.map(render_scene, compared, chunksize=1)
    return {
        "schema": SCHEMA,
        "generator": "python-checks/mitsuba_render.py",
        "regenerate": REGENERATE,
        "description": (
            f"The suite's physically based course scenes at {WIDTH}x{HEIGHT}, rendered by Mitsuba {mi.__version__} "
            f"({VARIANT}, float32): a Whitted integrator on Mitsuba's ray_intersect, fresnel_conductor, fresnel, "
            f"reflect, refract, with each pixel's edge mask; Mitsuba's path integrator through mi.render at "
            f"{PATH_WIDTH}x{PATH_HEIGHT}, box filter, {PATH_SAMPLES} passes of one sample per pixel, "
            "mean and standard deviation per pixel"
        ),
        "mitsuba": {"version": mi.__version__, "variant": VARIANT},
        "excluded": excluded,
        "scenes": entries,
    }


def select(document, name):
    """``document`` with the entries of scene ``name`` only, as ``build(name)``
    writes it."""
    return dict(document,
                excluded={k: v for k, v in document["excluded"].items() if k == name},
                scenes=[entry for entry in document["scenes"] if entry["name"] == name])


def to_text(document):
    """The file's text: what ``write`` writes."""
    return json.dumps(document, indent=1, sort_keys=False) + "\n"


def write(document, path):
    write_text(path, to_text(document))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("path", nargs="?", default=DEFAULT_PATH)
    parser.add_argument("--only", metavar="SCENE", help="one course scene's entry, as select() keeps it")
    args = parser.parse_args(argv[1:])
    path = args.path
    try:
        document = build(args.only)
    except SceneError as error:
        print(f"mitsuba_render.py: {error}", file=sys.stderr)
        return 1
    write(document, path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
