#!/usr/bin/env python3
"""Writes the 3D-camera genomes of the flam3 camera cross-check and their flat references.

flam3-render reads no cam_* attribute, so each genome NAME.flame (cam_pitch, cam_yaw,
cam_perspective, cam_zpos with a centre and a rotation) has a reference NAME_reference.flame that
flam3-render can draw: the same xforms with no camera attributes, plus a final xform that carries
the camera's projection of the plane z = 0 (where a planar genome lives). For a point (x, y, 0),
c = M(pitch, yaw) · (x, y, −zpos) and the picture plane shows (c_x, c_y) / (1 − perspective · c_z).
With u = c_x and v = the in-plane part of c_z, both linear in (x, y), that is a pre-affine map, flam3's
`perspective` variation (x·d/(d − y·sin a), y·d·cos a/(d − y·sin a)) and a post-affine map:
  c_z = v − cos(pitch)·zpos, so 1 − perspective·c_z = A·(1 − k·v), A = 1 + perspective·cos(pitch)·zpos, k = perspective/A;
  c_y = (cos(pitch)/sin(pitch))·v + sin(pitch)·zpos, i.e. β·v + γ;
  x_out = x''/A, y_out = ((β + γ·k)/(cos a · s)·y'' + γ)/A, where the pre-affine scales v by s so
  that sin a = k/s stays within (−1, 1).
flam3-render then applies the centre and rotation as it always does.

cam_dof moves the turned point by dr = rand · 0.1 · cam_dof · c_z at a random angle before the divide
(Apophysis 7X's ProjectPitchYawDOF). A level camera (pitch 0) keeps c_z = −zpos on the plane, so
the move has a constant reach R = 0.1 · cam_dof · |zpos|: flam3's own `blur` variation (a uniform
angle and a uniform distance up to its weight) in the final xform, beside `linear`, before the
post-affine divide by 1 − perspective · c_z. Run it from this folder.
"""
import math

GENOMES = {
    "julia": [
        'weight="1" color="0" color_speed="0.5" julia="0.8" linear="0.2" coefs="0.62 0.31 -0.31 0.62 0.35 0.1"',
        'weight="0.8" color="0.5" color_speed="0.5" linear="1" coefs="0.5 -0.2 0.2 0.5 -0.4 0.3"',
        'weight="0.6" color="1" color_speed="0.5" julia="0.5" linear="0.5" coefs="-0.4 0.3 -0.3 -0.4 0.1 -0.5"',
    ],
    "blur": [
        'weight="1" color="0" color_speed="0.5" linear="0.9" blur="0.1" coefs="0.55 0.0 0.0 0.55 0.45 0.0"',
        'weight="1" color="0.5" color_speed="0.5" linear="1" coefs="0.55 0.0 0.0 0.55 -0.45 0.0"',
        'weight="1" color="1" color_speed="0.5" linear="0.85" blur="0.15" coefs="0.5 0.1 -0.1 0.5 0.0 0.6"',
    ],
    "spherical": [
        'weight="1" color="0" color_speed="0.5" spherical="0.7" linear="0.3" coefs="0.7 0.2 -0.2 0.7 0.4 0.2"',
        'weight="1" color="0.5" color_speed="0.5" linear="1" coefs="0.45 -0.25 0.25 0.45 -0.5 0.1"',
        'weight="0.7" color="1" color_speed="0.5" spherical="0.8" linear="0.2" coefs="-0.5 0.1 -0.1 -0.5 0.2 -0.6"',
    ],
}
CAMERA = {"pitch": 0.7, "yaw": 0.4, "perspective": 0.25, "zpos": 0.3, "rotate": 25.0}
# Where each attractor's picture sits: the centre (on the picture plane, before the rotation) and scale.
VIEWS = {"julia": ((0.05, 0.13), 120.0), "blur": ((0.06, 0.65), 100.0), "spherical": ((0.15, -0.1), 70.0),
         "julia_orthographic": ((0.05, 0.13), 110.0)}
# The orthographic one: the same julia genome seen without perspective, from another side.
GENOMES["julia_orthographic"] = GENOMES["julia"]
CAMERAS = {"julia_orthographic": {"pitch": -0.9, "yaw": 2.2, "perspective": 0.0, "zpos": -0.4, "rotate": -60.0}}
# The lens blur: the julia genome seen level, its plane 1.0 behind the plane the camera keeps sharp.
GENOMES["julia_dof"] = GENOMES["julia"]
VIEWS["julia_dof"] = ((0.05, 0.13), 140.0)
CAMERAS["julia_dof"] = {"pitch": 0.0, "yaw": 0.4, "perspective": 0.25, "zpos": 1.0, "rotate": 25.0, "dof": 0.8}
HEADER = ('size="256 256" scale="{scale}" center="{cx} {cy}" rotate="{rotate}" oversample="1" filter="0.5" '
          'quality="60" background="0 0 0" brightness="4" gamma="2" gamma_threshold="0.01" vibrancy="1" '
          'highlight_power="1" estimator_radius="9" estimator_minimum="0" estimator_curve="0.4" palette="27"')


def num(v):
    return "%.12g" % v


def blurred_final_xform(cam):
    yaw, persp, zpos, dof = cam["yaw"], cam["perspective"], cam["zpos"], cam["dof"]
    assert cam["pitch"] == 0.0
    cy, sy = math.cos(-yaw), math.sin(-yaw)
    pre = (cy, -sy, 0.0, sy, cy, 0.0)  # c = M(0, yaw) · (x, y)
    zr = 1.0 + persp * zpos            # 1 − perspective · c_z, c_z = −zpos
    post = (1.0 / zr, 0.0, 0.0, 0.0, 1.0 / zr, 0.0)
    coefs = lambda m: " ".join(num(m[i]) for i in (0, 3, 1, 4, 2, 5))
    return ('<finalxform color="0" color_speed="0" linear="1" blur="%s" coefs="%s" post="%s"/>'
            % (num(0.1 * dof * abs(zpos)), coefs(pre), coefs(post)))


def reference_final_xform(cam):
    if cam.get("dof"):
        return blurred_final_xform(cam)
    pitch, yaw, persp, zpos = cam["pitch"], cam["yaw"], cam["perspective"], cam["zpos"]
    cy, sy, cp, sp = math.cos(-yaw), math.sin(-yaw), math.cos(pitch), math.sin(pitch)
    m0 = (cy, -sy)
    m2 = (sp * sy, sp * cy)
    a0 = 1.0 + persp * cp * zpos
    k = persp / a0
    s = max(1.0, 2.0 * abs(k))
    sin_a = k / s
    cos_a = math.sqrt(1.0 - sin_a * sin_a)
    beta, gamma = cp / sp, sp * zpos
    pre = (m0[0], m0[1], 0.0, s * m2[0], s * m2[1], 0.0)  # a b c d e f
    post = (1.0 / a0, 0.0, 0.0, 0.0, (beta + gamma * k) / (cos_a * s * a0), gamma / a0)
    coefs = lambda m: " ".join(num(m[i]) for i in (0, 3, 1, 4, 2, 5))  # the file's "a d b e c f"
    angle = math.asin(sin_a) * 2.0 / math.pi  # flam3's perspective_angle is in quarter turns
    return ('<finalxform color="0" color_speed="0" perspective="1" perspective_angle="%s" perspective_dist="1" '
            'coefs="%s" post="%s"/>' % (num(angle), coefs(pre), coefs(post)))


def main():
    for name, xforms in GENOMES.items():
        cam = CAMERAS.get(name, CAMERA)
        camera = 'cam_pitch="%s" cam_yaw="%s" cam_perspective="%s" cam_zpos="%s"' % (
            num(cam["pitch"]), num(cam["yaw"]), num(cam["perspective"]), num(cam["zpos"]))
        if cam.get("dof"):
            camera += ' cam_dof="%s"' % num(cam["dof"])
        (cx, cy), scale = VIEWS[name]
        header = HEADER.format(scale=num(scale), cx=num(cx), cy=num(cy), rotate=num(cam["rotate"]))
        body = "".join("   <xform %s/>\n" % x for x in xforms)
        with open(name + ".flame", "w") as f:
            f.write('<flame name="%s" %s %s>\n%s</flame>\n' % (name, header, camera, body))
        with open(name + "_reference.flame", "w") as f:
            f.write('<flame name="%s" %s>\n%s   %s\n</flame>\n' % (name, header, body, reference_final_xform(cam)))


if __name__ == "__main__":
    main()
