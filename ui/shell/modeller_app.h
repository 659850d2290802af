#pragma once
// The interactive modeller. app/open_modeller.cpp hands off here.
#include <string>

namespace gridifs::ui {

/// Opens the modeller window on `file` (the default project when empty) and runs it until the
/// artist quits. argv may carry window options (see modeller_options.h), e.g.
/// `gridifs FILE --screenshot OUT.png --frames N`. Returns the process exit code: 0 on success,
/// 1 when no window can be opened, 2 for bad options.
int runModeller(const std::string& file, int argc, char** argv);

}  // namespace gridifs::ui
