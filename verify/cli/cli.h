/* The gdsmc command line (docs/command-line.md).  Exit status: 0 success, 1 a
 * verification check failed, 2 bad input or any other error (nothing is
 * written then). */
#ifndef GDSMC_VFY_CLI_H
#define GDSMC_VFY_CLI_H

int gdsmc_main(int argc, char **argv);

#endif
