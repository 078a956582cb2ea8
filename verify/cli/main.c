#include "cli.h"

#ifdef GDSMC_MPI
#include <mpi.h>
#include <stdio.h>

#include "table.h"

/* Built with GDSMC_MPI: `mpiexec -n R gdsmc COMMAND ...` runs the same command
 * on every rank; sim_ensemble_run shares each run's ensembles out across them
 * and gives every rank the same numbers as one process would (sim/ensemble.c).
 * Only rank 0 speaks: the others write no files (vfy_set_writes_files) and
 * their standard output and error go to /dev/null.  OpenMP threads run inside
 * each rank, and only the main thread calls MPI: MPI_THREAD_FUNNELED. */
int main(int argc, char **argv)
{
    int provided = MPI_THREAD_SINGLE, rank = 0;
    if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        fputs("gdsmc: MPI_Init_thread failed\n", stderr);
        return 2;
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    int ready = provided >= MPI_THREAD_FUNNELED;
    if (rank != 0) {
        vfy_set_writes_files(0);
        ready = ready && freopen("/dev/null", "w", stdout) != NULL
                && freopen("/dev/null", "w", stderr) != NULL;
    }
    /* all ranks run the command or none does: its collectives need every rank */
    MPI_Allreduce(MPI_IN_PLACE, &ready, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    int rc = 2;
    if (ready)
        rc = gdsmc_main(argc, argv);
    else if (provided < MPI_THREAD_FUNNELED)
        fputs("gdsmc: this MPI library does not support MPI_THREAD_FUNNELED, which the "
              "OpenMP threads inside each rank need\n", stderr);
    else
        fputs("gdsmc: a rank could not redirect its output to /dev/null\n", stderr);
    fflush(stdout);
    fflush(stderr);
    MPI_Finalize();
    return rc;
}
#else
int main(int argc, char **argv) { return gdsmc_main(argc, argv); }
#endif
