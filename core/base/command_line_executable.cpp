#include "base/command_line_executable.h"

namespace gridifs {

std::filesystem::path besideThisExecutable(const std::string& fileName, std::error_code& error) {
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path() : self.parent_path() / fileName;
}

std::filesystem::path commandLineExecutable(std::error_code& error) {
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return {};
  if (self.filename() == kModellerFileName) {
    std::error_code ignored;
    const std::filesystem::path sibling = self.parent_path() / kCommandLineFileName;
    if (std::filesystem::is_regular_file(sibling, ignored)) return sibling;
  }
  return self;
}

}  // namespace gridifs
