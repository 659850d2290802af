#pragma once
// The camera as a file for compositing and 3D packages (gridifs export-camera): USD's text form
// (.usda, a UsdGeomCamera whose transform is sampled per frame) and Nuke's channel file (.chan).
//
// USD: the camera looks down its local −z with +y up, as GridIFS's view space does
// (render/camera.h), in GridIFS's world (+z up: the stage says upAxis "Z"); xformOp:transform is
// the camera-to-world matrix in USD's row-vector order; apertures and focal length in tenths of a
// world unit (USD's convention), so a perspective camera's vertical field of view is
// 2·atan(verticalAperture / (2·focalLength)). A panoramic camera is written as the perspective
// camera along its view axis, with its projection and field of view as "gridifs:projection" and
// "gridifs:fov" custom attributes (UsdGeomCamera has no fisheye or equirectangular projection).
//
// .chan: one line per frame, "frame tx ty tz rx ry rz vfov", in a +y-up world (GridIFS's
// (x, y, z) is (x, z, −y) there, as Nuke and Houdini expect); rotations in degrees in Nuke's
// default order ZXY (camera-to-world R = Ry · Rx · Rz); vfov the vertical field of view in degrees.
//
// Thread-safety: pure functions.
#include <string>
#include <vector>

#include "model/project.h"

namespace gridifs {

/// The camera at one frame.
struct CameraSample {
  double frame = 0.0;
  Camera camera;
};

/// A .usda stage holding the camera "/camera" for a width × height image, sampled at `samples`
/// (their frames are the time codes, `fps` time codes per second). One sample: a still camera.
std::string cameraUsda(const std::vector<CameraSample>& samples, int width, int height, double fps);

/// A .chan file of `samples` for a width × height image.
std::string cameraChan(const std::vector<CameraSample>& samples, int width, int height);

}  // namespace gridifs
