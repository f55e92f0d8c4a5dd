// Entry point: the stock LIGGGHTS main(), plus our style registration.
// Command-line switches (-in, -var, -echo, -log, -screen, ...) are parsed by
// LAMMPS' constructor exactly as in the `liggghts` executable.

#include <mpi.h>
#include <signal.h>
#include <string.h>

#include "lammps.h"
#include "input.h"
#include "signal_handling.h"

#include "register_styles.h"

using namespace LAMMPS_NS;

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

  MPI_Init(&argc, &argv);

  LAMMPS *lammps = new LAMMPS(argc, argv, MPI_COMM_WORLD);
  register_project_styles(lammps);
  lammps->input->file();
  delete lammps;

  MPI_Finalize();
  return 0;
}
