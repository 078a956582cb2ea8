#include "cli.h"

int main(int argc, char **argv) { return gdsmc_main(argc, argv); }
