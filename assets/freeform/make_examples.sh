#!/bin/sh
# Regenerates the free-form examples of Thollot, Zair, Tosan & Vandorpe's figures 5.1–5.5 with
# the command line (GRIDIFS: the executable, default gridifs on the PATH); jq only turns cameras
# and lays the second curve of the tensor products along y.
set -eu
G=${GRIDIFS:-gridifs}
cd "$(dirname "$0")"
camera() { # FILE YAW PITCH DISTANCE
  jq ".camera.yaw = $2 | .camera.pitch = $3 | .camera.distance = $4" "$1" > "$1.tmp" && mv "$1.tmp" "$1"
}
along_y() { # FILE: control points (x, y, z) → (y, x, 0.4·z), a gentle curve along y
  jq '.space.control_points |= map([.[1], .[0], 0.4 * .[2]])' "$1" > "$1.tmp" && mv "$1.tmp" "$1"
}
flatter() { # FILE: control points (x, y, z) → (x, y, 0.4·z)
  jq '.space.control_points |= map([.[0], .[1], 0.4 * .[2]])' "$1" > "$1.tmp" && mv "$1.tmp" "$1"
}

# 5.1: a Bézier curve and a fractal curve with the same control points.
$G free-form -o fig5_1_bezier_curve.gridifs --preset bezier-curve --degree 3
$G free-form -o fig5_1_fractal_curve.gridifs --preset bezier-curve --degree 3 --roughness 0.45 --seed 3
camera fig5_1_bezier_curve.gridifs 90 5 3.2
camera fig5_1_fractal_curve.gridifs 90 5 3.2

# 5.2: the sum of a tree and a parabola: the tree's affine IFS on a triangle (F̂, degree 1) and a
# quadratic Bézier curve (a small parabola in the tree's plane), the sum by the tensor product of their
# matrices (every pair T_i ⊗ T'_j; its attractor is A + A', Thollot et al. §5.4.1).
$G free-form -o tree_on_a_triangle.gridifs --from tree_grid.gridifs --degree 1
$G free-form -o parabola.gridifs --preset bezier-curve --degree 2
jq '.space.control_points = [[-0.3, 0.25, 0], [0, -0.25, 0], [0.3, 0.25, 0]]' parabola.gridifs > parabola.tmp && mv parabola.tmp parabola.gridifs
$G combine tree_on_a_triangle.gridifs parabola.gridifs --op product -o fig5_2_tree_plus_parabola.gridifs
camera fig5_2_tree_plus_parabola.gridifs -90 89 5.5

# 5.3: tensor products: a Bézier curve with a fractal one, and two fractal curves.
$G free-form -o smooth_s.gridifs --preset bezier-curve
$G free-form -o fractal_s.gridifs --preset bezier-curve --roughness 0.7 --seed 5
$G free-form -o fractal_t.gridifs --preset bezier-curve --roughness 0.7 --seed 9
flatter smooth_s.gridifs
flatter fractal_s.gridifs
along_y fractal_t.gridifs
$G combine smooth_s.gridifs fractal_t.gridifs --op product -o fig5_3_bezier_times_fractal.gridifs
$G combine fractal_s.gridifs fractal_t.gridifs --op product -o fig5_3_fractal_times_fractal.gridifs
camera fig5_3_bezier_times_fractal.gridifs 20 55 4.5
camera fig5_3_fractal_times_fractal.gridifs 20 55 4.5
rm smooth_s.gridifs fractal_s.gridifs fractal_t.gridifs

# 5.4: smooth and fractal deformation of the Sierpinski gasket (three quarters of a patch).
$G free-form -o fig5_4_smooth_gasket.gridifs --preset sierpinski-patch
$G free-form -o fig5_4_fractal_gasket.gridifs --preset sierpinski-patch --roughness 0.7
camera fig5_4_smooth_gasket.gridifs 0 80 4.0
camera fig5_4_fractal_gasket.gridifs 0 80 4.0

# 5.5: the gasket deformed by quadratic functions, F̂ of its grid IFS on a paraboloid net.
$G free-form -o fig5_5_elliptic_paraboloid.gridifs --from sierpinski_gasket_grid.gridifs --net elliptic-paraboloid --height 0.6
$G free-form -o fig5_5_hyperbolic_paraboloid.gridifs --from sierpinski_gasket_grid.gridifs --net hyperbolic-paraboloid --height 0.6
camera fig5_5_elliptic_paraboloid.gridifs 30 30 4.6
camera fig5_5_hyperbolic_paraboloid.gridifs 30 30 4.6
rm -f ./*.gridifs~  # the backups saving keeps
# jq's output in GridIFS's own saved form (what the shipped-projects test holds assets/ to).
"${GRIDIFS_RESAVE:-../../build/tests/gridifs_resave_project}" ./*.gridifs
rm -f ./*.gridifs~  # and the ones resaving keeps
