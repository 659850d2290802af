#pragma once
// The polygon mesh type of the deterministic algorithm (Gröller & Wegenkittl 1994, §3.2): an OpenMesh
// PolyMesh with float points, float RGBA vertex colors in [0, 1] and a per-face `address` property.
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <cstdint>
#include <vector>

namespace gridifs {

struct IfsMeshTraits : public OpenMesh::DefaultTraits {
  // Float points: what PLY/OBJ/OFF/STL consumers expect, and half the memory of doubles for
  // meshes of tens of millions of faces. Geometry is computed in double before it is stored.
  using Point = OpenMesh::Vec3f;
  using Normal = OpenMesh::Vec3f;
  // Float RGBA in [0, 1]; OpenMesh's writers convert to the file's 8-bit RGB. Not Vec3uc: its
  // default constructor leaves bytes uninitialised, which GCC 12 -O3 flags in every property
  // push_back; not Vec3f: OpenMesh 9's exporter cannot cast it to the integer colors it writes.
  using Color = OpenMesh::Vec4f;
  VertexAttributes(OpenMesh::Attributes::Color);
};

/// A base mesh or a result F^n(A). Not thread-safe for writes (OpenMesh), safe to read concurrently.
using IfsMesh = OpenMesh::PolyMesh_ArrayKernelT<IfsMeshTraits>;

/// Name of the per-face int property holding the copy's address code (see decodeAddress). It is
/// persistent, so binary/ASCII PLY files carry it as `property int address` on faces.
inline constexpr const char* kAddressPropertyName = "address";

/// The per-face address property of `mesh`, or an invalid handle when it has none.
inline OpenMesh::FPropHandleT<int> addressProperty(const IfsMesh& mesh) {
  OpenMesh::FPropHandleT<int> handle;
  mesh.get_property_handle(handle, kAddressPropertyName);
  return handle;
}

/// A copy of F^n(A) is f_{a1} ∘ f_{a2} ∘ … ∘ f_{an}(A) (a1 applied last, outermost). Its address
/// code is Σ a_k · N^(n−k), so a1 is the most significant base-N digit and copies sorted by code
/// are sorted by address. Returns (a1, …, an); digits index DeterministicIfs::maps.
inline std::vector<int> decodeAddress(std::uint64_t code, int functionCount, int depth) {
  std::vector<int> digits(depth > 0 ? std::size_t(depth) : 0u);
  for (int k = depth - 1; k >= 0; --k) {
    digits[std::size_t(k)] = int(code % std::uint64_t(functionCount));
    code /= std::uint64_t(functionCount);
  }
  return digits;
}

}  // namespace gridifs
