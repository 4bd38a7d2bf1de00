"""The area lights that stand in for the delta lights deliver the delta
lights' irradiance (a uniform sphere's irradiance is a point's at its
centre; a disk of angular radius alpha gives L pi sin^2 alpha head-on), the
measured scene is the course scene with Lambert for the course's rough
material, the regions are what the camera sees, and the committed
reference regenerates byte for byte."""
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_full_light as fl  # noqa: E402
import mitsuba_render as mr  # noqa: E402

import mitsuba as mi  # noqa: E402


def plane_scene(light):
    """A white Lambert plane at z = 4 facing the course camera, one light."""
    return {
        "version": 1,
        "image": {"width": 9, "height": 9},
        "camera": {"type": "course_pinhole"},
        "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
        "objects": [{"type": "plane", "point": [0, 0, 4], "normal": [0, 0, -1], "material": "m"}],
        "lights": [light],
    }


def centre_radiance(scene, estimate, samples):
    """Mitsuba's mean radiance at the centre pixel's centre, and its standard error."""
    d = fl.mitsuba_dict(scene, estimate)
    d["sensor"] = mr.mitsuba_sensor(scene["camera"], 9, 9)
    m = mi.load_dict(d, optimize=False)
    ray = mr.pixel_ray(m.sensors()[0], 4, 4, 9, 9)
    sampler = mi.load_dict({"type": "independent"})
    sampler.seed(0)
    values = []
    for _ in range(samples):
        value, _, _ = m.integrator().sample(m, sampler, mi.RayDifferential3f(ray))
        values.append(float(value[0]))
        sampler.advance()
    mean = sum(values) / samples
    variance = sum((v - mean) ** 2 for v in values) / (samples - 1)  # samples >= 2
    return mean, math.sqrt(variance / samples)


def test_a_sphere_of_radiance_i_over_pi_r_squared_lights_as_a_point_of_intensity_i():
    # E = I / d^2 head-on at d = 2: L = albedo / pi * E, exactly for a
    # uniform sphere wholly above the horizon.
    scene = plane_scene({"type": "point", "position": [0, 0, 2], "intensity": [8, 8, 8]})
    expected = 0.5 / math.pi * 8 / 4
    point, _ = centre_radiance(scene, "path", 2)
    assert abs(point - expected) < 1e-5
    area, se = centre_radiance(scene, "area", 4096)
    # Five standard errors, and the sphere's own emission sampling's float32.
    assert abs(area - expected) < 5 * se + 1e-5, (area, expected, se)
    # The test's power: a sphere of a quarter of that radiance (I / (4 pi r^2),
    # its intensity taken for its power per steradian of the whole sphere's
    # area) is far outside it.
    assert abs(area - expected / 4) > 5 * se + 1e-5


def test_a_distant_disk_of_radiance_e_over_pi_sin2_alpha_lights_as_a_directional_light():
    towards = [math.sin(math.pi / 3), 0, -math.cos(math.pi / 3)]
    scene = plane_scene({"type": "directional", "towards": towards, "irradiance": [2, 2, 2]})
    expected = 0.5 / math.pi * 2 * 0.5
    area, se = centre_radiance(scene, "area", 4096)
    # Over a disk of angular radius alpha the cosine 0.5 moves by its
    # second-order mean, sin(60°) alpha^2 / 4... bounded here by alpha^2.
    assert abs(area - expected) < 5 * se + expected * fl.ANGULAR_RADIUS ** 2, (area, expected, se)
    lights = fl.area_lights(scene)[1]
    assert lights[0]["type"] == "disk"
    assert abs(lights[0]["radiance"][0] * math.pi * math.sin(fl.ANGULAR_RADIUS) ** 2 - 2.0) < 1e-12


def test_the_sphere_clears_every_surface():
    with open(os.path.join(fl.ROOT, "crates/tracer/scenes/kaleidoscope_lit.json"), encoding="utf-8") as f:
        scene = fl.measured_scene(json.load(f))
    p = scene["lights"][0]["position"]
    r = fl.area_lights(scene)[1][0]["radius"]
    assert 0 < r < fl.distance_to_surfaces(scene, p)
    # The tube's inscribed radius 2.5 cos(pi / sides) bounds the distance from the axis.
    assert fl.distance_to_surfaces(scene, p) <= 2.5


def test_the_measured_scene_is_the_course_scene_with_lambert_for_the_rough_material():
    with open(os.path.join(fl.ROOT, "crates/tracer/scenes/shadow.json"), encoding="utf-8") as f:
        course = json.load(f)
    scene = fl.measured_scene(course)
    assert scene["materials"]["green"] == {"type": "lambert", "albedo": course["materials"]["green"]["diffuse"]}
    assert scene["objects"] == course["objects"] and scene["lights"] == course["lights"]
    assert scene["background"] == [0, 0, 0]
    assert scene["render"]["integrator"] == "path" and scene["render"]["throughput_cutoff"] == 0



def test_the_measured_scenes_are_the_course_scenes_less_the_excluded_ones():
    # A scene added to the course list is measured unless excluded with a
    # reason; an exclusion names a scene that is on the list.
    assert set(fl.EXCLUDED) <= set(mr.course_scenes())
    assert fl.SCENES == [name for name in mr.course_scenes() if name not in fl.EXCLUDED]
    assert fl.SCENES, "no scene measured"
