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
#include "base/command_line_executable.h"

#ifdef GRIDIFS_HAVE_GUI
#include "ui/shell/modeller_app.h"
#endif

namespace gridifs::cli {

int openModeller(const std::string& file, int argc, char** argv) {
#if defined(GRIDIFS_HAVE_GUI)
  return ui::runModeller(file, argc, argv);
#elif defined(GRIDIFS_EXEC_MODELLER)
  (void)file;
  (void)argc;
  std::error_code ec;
  const std::filesystem::path modeller = besideThisExecutable(kModellerFileName, ec);
  std::cout.flush();
  std::cerr.flush();
  if (!ec) execv(modeller.c_str(), argv);
  std::cerr << "gridifs: cannot start the modeller window ("
            << (ec ? std::string(kModellerFileName) : modeller.string())
            << "): " << (ec ? ec.message() : std::strerror(errno)) << ".\n";
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
