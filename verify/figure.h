/* Figures with gnuplot (SPEC §9), when it is installed. */
#ifndef GDSMC_VFY_FIGURE_H
#define GDSMC_VFY_FIGURE_H

/* Run `gnuplot script_path` (the script names its own PNG output).  Returns
 * 1 if gnuplot ran and succeeded, 0 if gnuplot is not installed or this
 * process writes no files (vfy_writes_files), -1 if it failed. */
int vfy_gnuplot(const char *script_path);

#endif
