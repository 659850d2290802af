#pragma once
// OpenVDB files of the density volume: what Blender's Principled Volume and Houdini open as
// dropped in.
#include <filesystem>

#include "volume/density_volume.h"

namespace gridifs {

/// Writes `volume` to `file` atomically: a FloatGrid "density" of class fog volume (background 0,
/// only non-zero voxels active) and, when the volume has colour, a Vec3SGrid "color"; index
/// (i, j, k) is voxel (i, j, k), the transform linear with voxel size 2/N and translation −1 + 1/N.
/// Throws IoError naming the file.
void writeVdbVolume(const DensityVolume& volume, const std::filesystem::path& file);

/// Throws IoError when VDB files cannot be written here (the OpenVDB plugin cannot be loaded), so
/// a long computation can fail before it starts rather than at the end.
void requireVdbVolumeWriter();

}  // namespace gridifs
