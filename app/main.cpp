// Entry point: the stock LIGGGHTS main(), plus our style registration.
// Command-line switches (-in, -var, -echo, -log, -screen, ...) are parsed by
// LAMMPS' constructor exactly as in the `liggghts` executable.

#include <mpi.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "lammps.h"
#include "input.h"
#include "signal_handling.h"

#include "register_styles.h"

using namespace LAMMPS_NS;

// Errors visible with any redirection.  LIGGGHTS' Error::one (src/error.cpp) prints
// "ERROR on proc N: ..." to `screen` (stdout on every rank unless -screen) and then calls
// MPI_Abort, which kills the process without flushing stdio: with stdout redirected to a
// file or a pipe (fully buffered) the message, and the end of the log file, were lost.
// main() makes stdout (and stderr) line-buffered, and this definition of MPI_Abort, which
// libliggghts' calls bind to (exported_symbols.list; the MPI profiling interface),
// flushes every open stdio stream (screen, log file, -screen file) before aborting.
extern "C" int MPI_Abort(MPI_Comm comm, int errorcode)
{
  fflush(nullptr);
  return PMPI_Abort(comm, errorcode);
}

int main(int argc, char **argv)
{
  // As stock LIGGGHTS: SIGINT/SIGTERM request a clean quit, SIGUSR1 a restart file.
  struct sigaction int_action, usr1_action;
  memset(&int_action, 0, sizeof(int_action));
  memset(&usr1_action, 0, sizeof(usr1_action));
  int_action.sa_handler = SignalHandler::int_handler;
  sigaction(SIGINT, &int_action, nullptr);
  sigaction(SIGTERM, &int_action, nullptr);
  usr1_action.sa_handler = SignalHandler::usr1_handler;
  sigaction(SIGUSR1, &usr1_action, nullptr);

  // before any output (setvbuf must come first on a stream)
  setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
  setvbuf(stderr, nullptr, _IONBF, 0);

  MPI_Init(&argc, &argv);

  LAMMPS *lammps = new LAMMPS(argc, argv, MPI_COMM_WORLD);
  register_project_styles(lammps);
  lammps->input->file();
  delete lammps;

  MPI_Finalize();
  return 0;
}
