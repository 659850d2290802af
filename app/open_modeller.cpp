// Opening the modeller: the GUI build hands off to ui/; without it, say so clearly.
#include <iostream>

#include "app/cli.h"

#ifdef GRIDIFS_HAVE_GUI
#include "ui/shell/modeller_app.h"
#endif

namespace gridifs::cli {

int openModeller(const std::string& file, int argc, char** argv) {
#ifdef GRIDIFS_HAVE_GUI
  return ui::runModeller(file, argc, argv);
#else
  (void)argc;
  (void)argv;
  std::cerr << "gridifs: this build has no modeller window" << (file.empty() ? "" : " to open " + file)
            << "; use a verb such as 'gridifs info FILE' (see 'gridifs --help').\n";
  return kBadInput;
#endif
}

}  // namespace gridifs::cli
