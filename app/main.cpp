// gridifs: parse the command line, then run one verb or open the modeller.
#include "app/cli.h"

int main(int argc, char** argv) { return gridifs::cli::run(argc, argv); }
