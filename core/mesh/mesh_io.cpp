#include "mesh/mesh_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstring>
#include <fstream>
#include <mutex>
#include <new>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/text_format.h"
#include "base/types.h"

namespace gridifs {
namespace fs = std::filesystem;

namespace {

// OpenMesh reports problems on its global omerr()/omlog()/omout() streams (std::cerr by
// default), e.g. a line per face of a non-manifold file. The CLI promises one clear sentence on
// stderr, so the streams are muted while we read or write; our own checks say what went wrong.
// (Muting, not redirecting: OpenMesh 9's mostream::disconnect leaks its target on every call.)
// The lock keeps two threads doing mesh IO from unmuting each other.
class QuietOpenMesh {
 public:
  QuietOpenMesh() : lock_(mutex()) {
    ::omerr().disable();
    ::omlog().disable();
    ::omout().disable();
  }
  ~QuietOpenMesh() {
    ::omerr().flush();  // drops what was buffered while muted
    ::omerr().enable();
    ::omlog().enable();
    ::omout().enable();
  }
  QuietOpenMesh(const QuietOpenMesh&) = delete;
  QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  std::lock_guard<std::mutex> lock_;
};

const char* extensionOf(MeshFormat format) {
  switch (format) {
    case MeshFormat::Ply:
      return ".ply";
    case MeshFormat::Obj:
      return ".obj";
    case MeshFormat::Stl:
      return ".stl";
    case MeshFormat::Off:
      return ".off";
  }
  return ".ply";
}

// A sibling of `file` that no other writer uses: same folder (so rename is atomic), hidden,
// unique per process and call.
fs::path temporarySibling(const fs::path& file, const char* tag) {
  static std::atomic<unsigned> counter{0};
  const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
  return folder / ("." + file.filename().string() + "." + tag + "-" + std::to_string(::getpid()) + "-" +
                   std::to_string(counter++));
}

std::string describe(const std::error_code& error) {
  std::string text = error.message();
  if (!text.empty()) text[0] = char(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

}  // namespace

std::optional<MeshFormat> meshFormatFromPath(const fs::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == "ply") return MeshFormat::Ply;
  if (ext == "obj") return MeshFormat::Obj;
  if (ext == "stl") return MeshFormat::Stl;
  if (ext == "off") return MeshFormat::Off;
  return std::nullopt;
}

const char* meshFormatName(MeshFormat format) {
  switch (format) {
    case MeshFormat::Ply:
      return "PLY";
    case MeshFormat::Obj:
      return "OBJ";
    case MeshFormat::Stl:
      return "STL";
    case MeshFormat::Off:
      return "OFF";
  }
  return "?";
}

bool formatHasVertexColors(MeshFormat format) { return format == MeshFormat::Ply || format == MeshFormat::Off; }
bool formatNeedsTriangles(MeshFormat format) { return format == MeshFormat::Stl; }

namespace {

/// The element counts an OFF, PLY or binary STL header declares, checked against the file's size
/// before OpenMesh reserves memory for them: every vertex or face takes at least one byte (binary
/// STL: exactly 50 per triangle), so a larger count is a hostile or truncated header. Returns the
/// reason, or an empty string when the counts can be true.
std::string implausibleHeader(const fs::path& file, MeshFormat format, std::uintmax_t bytes) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return {};
  auto tooMany = [&](double declared) { return declared > double(bytes); };
  if (format == MeshFormat::Off) {
    std::string magic;
    double vertices = 0, faces = 0;
    in >> magic;
    if (magic.find("OFF") == std::string::npos || !(in >> vertices >> faces)) return {};
    if (vertices < 0 || faces < 0 || tooMany(vertices + faces))
      return "its header declares more vertices or faces than the file can hold";
  } else if (format == MeshFormat::Ply) {
    std::string line;
    double total = 0;
    for (int n = 0; n < 1000 && std::getline(in, line) && line.rfind("end_header", 0) != 0; ++n) {
      std::istringstream words(line);
      std::string keyword, element;
      double count = 0;
      if (words >> keyword >> element >> count && keyword == "element") {
        if (count < 0) return "its header declares a negative element count";
        total += count;
      }
    }
    if (tooMany(total)) return "its header declares more vertices or faces than the file can hold";
  } else if (format == MeshFormat::Stl) {
    char head[84] = {};
    if (!in.read(head, sizeof head) || std::string_view(head, 5) == "solid") return {};  // ASCII STL
    std::uint32_t triangles = 0;
    std::memcpy(&triangles, head + 80, 4);
    if (84.0 + 50.0 * triangles > double(bytes)) return "its header declares more triangles than the file holds";
  }
  return {};
}

}  // namespace

IfsMesh readMeshFile(const fs::path& file) {
  const std::string name = file.string();
  const auto format = meshFormatFromPath(file);
  if (!format) throw ModelError("", name + " is not a mesh file OpenMesh can read (use .obj, .ply, .stl or .off)");
  std::error_code error;
  const fs::file_status status = fs::status(file, error);
  if (error || !fs::exists(status))
    throw ModelError("", "cannot read " + name + ": " + (error ? describe(error) : "no such file"));
  if (fs::is_directory(status)) throw ModelError("", "cannot read " + name + ": it is a folder");
  const std::uintmax_t bytes = fs::file_size(file, error);
  if (error) throw ModelError("", "cannot read " + name + ": " + describe(error));
  if (bytes == 0) throw ModelError("", name + " is empty");
  if (bytes > kMaxMeshFileBytes) throw ModelError("", name + " is larger than 1 GiB, too large for a base mesh");
  if (::access(file.c_str(), R_OK) != 0) throw ModelError("", "cannot read " + name + ": permission denied");
  if (const std::string reason = implausibleHeader(file, *format, bytes); !reason.empty())
    throw ModelError("", "cannot read " + name + " as " + meshFormatName(*format) + ": " + reason);

  IfsMesh mesh;
  // Face status lets OpenMesh's importer mark the faces it could only add by duplicating
  // vertices (complex edges / vertices): the caller decides whether that is acceptable.
  mesh.request_face_status();
  mesh.request_vertex_status();
  mesh.request_edge_status();
  OpenMesh::IO::Options options;  // positions and faces only: base-mesh colors are not used
  bool ok = false;
  std::string message;
  {
    QuietOpenMesh quiet;
    try {
      ok = OpenMesh::IO::read_mesh(mesh, file.string(), options);
    } catch (const std::bad_alloc&) {  // OpenMesh reserves what the header declares
      ok = false;
      message = "its header declares more vertices or faces than fit in memory";
    } catch (const std::exception& e) {
      ok = false;
      message = e.what();
    }
  }
  if (!ok)
    throw ModelError("", "cannot read " + name + " as " + meshFormatName(*format) +
                             (message.empty() ? std::string() : ": " + message));
  return mesh;
}

void checkMeshOutputPath(const fs::path& file) {
  const std::string name = file.string();
  if (!meshFormatFromPath(file))
    throw ModelError(
        "", "cannot write " + name + ": unknown mesh format " +
                (file.extension().empty() ? std::string("(no extension)") : "\"" + file.extension().string() + "\"") +
                " (use .ply, .obj, .stl or .off)");
  std::error_code error;
  if (fs::is_directory(file, error)) throw ModelError("", "cannot write " + name + ": it is a folder");
  const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
  if (!fs::is_directory(folder, error))
    throw ModelError("", "cannot write " + name + ": the folder " + folder.string() + " does not exist");
  const fs::path probe = temporarySibling(file, "probe");
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) {
    const std::error_code why(errno, std::generic_category());
    throw ModelError("", "cannot write " + name + ": " + describe(why));
  }
  ::close(fd);
  fs::remove(probe, error);  // the folder is writable, so renaming over `file` will work too
}

void writeMeshFile(const IfsMesh& mesh, const fs::path& file, const MeshWriteOptions& options) {
  const std::string name = file.string();
  const auto format = meshFormatFromPath(file);
  if (!format) throw ModelError("", "cannot write " + name + ": unknown mesh format (use .ply, .obj, .stl or .off)");
  OpenMesh::IO::Options flags;
  if (options.binary && (*format == MeshFormat::Ply || *format == MeshFormat::Stl))
    flags += OpenMesh::IO::Options::Binary;
  if (options.vertexColors && formatHasVertexColors(*format) && mesh.has_vertex_colors())
    flags += OpenMesh::IO::Options::VertexColor;

  AtomicFile atomic(file);
  const fs::path& temporary = atomic.temporaryPath();
  auto fail = [&](const std::string& why) {
    throw IoError("cannot write " + name + (why.empty() ? std::string() : ": " + why));
  };
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) fail(describe(std::error_code(errno, std::generic_category())));
    bool ok = false;
    std::string message;
    {
      QuietOpenMesh quiet;
      try {
        // 9 significant digits round-trip a float exactly in the ASCII formats.
        ok = OpenMesh::IO::write_mesh(mesh, out, extensionOf(*format), flags, 9);
      } catch (const std::exception& e) {
        message = e.what();
      }
    }
    out.flush();
    if (!ok || !out) fail(!ok ? (message.empty() ? "OpenMesh's writer failed" : message) : "the disk may be full");
    out.close();
    if (!out) fail("the disk may be full");
  }
  atomic.commit();
}

}  // namespace gridifs
