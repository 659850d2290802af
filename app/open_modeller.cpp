// Opening the modeller. gridifs-modeller hands off to ui/. gridifs, the command line, links no
// window library (app/CMakeLists.txt): it execs gridifs-modeller beside it with the same
// arguments, so the process, its id and its exit code stay the ones the caller started. Without a
// GUI build, say so clearly.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "app/cli.h"

#ifdef GRIDIFS_HAVE_GUI
#include "ui/shell/modeller_app.h"
#endif

namespace gridifs::cli {

int openModeller(const std::string& file, int argc, char** argv) {
#if defined(GRIDIFS_HAVE_GUI)
  return ui::runModeller(file, argc, argv);
#elif defined(GRIDIFS_MODELLER_EXECUTABLE)
  (void)file;
  (void)argc;
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path modeller =
      (ec ? std::filesystem::path() : self.parent_path()) / GRIDIFS_MODELLER_EXECUTABLE;
  std::cout.flush();
  std::cerr.flush();
  execv(modeller.c_str(), argv);
  std::cerr << "gridifs: cannot start the modeller window (" << modeller.string() << "): " << std::strerror(errno)
            << ".\n";
  return kFailure;
#else
  (void)argc;
  (void)argv;
  std::cerr << "gridifs: this build has no modeller window" << (file.empty() ? "" : " to open " + file)
            << "; use a verb such as 'gridifs info FILE' (see 'gridifs --help').\n";
  return kBadInput;
#endif
}

}  // namespace gridifs::cli
