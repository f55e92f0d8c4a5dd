#include "membrane_polyline_file.h"

#include <mpi.h>

#include <cerrno>
#include <cstring>

#include "comm.h"
#include "error.h"

#include "membrane_output.h"
#include "style_args.h"

MembranePolylineFile::~MembranePolylineFile()
{
  if (fp_) std::fclose(fp_);
}

void MembranePolylineFile::open(const std::string &file)
{
  char reason[256] = "";
  if (comm->me == 0) {
    fp_ = std::fopen(file.c_str(), "w");
    if (!fp_) std::snprintf(reason, sizeof(reason), "%s", std::strerror(errno));
  }
  MPI_Bcast(reason, sizeof(reason), MPI_CHAR, 0, world);
  if (reason[0])
    error->all(FLERR, keyword_message(prefix_, "polyline", file,
                                      std::string("cannot open the file for writing (") + reason +
                                          "); check that its folder exists and is writable")
                          .c_str());
  open_ = true;
}

void MembranePolylineFile::write(LAMMPS_NS::bigint step, const membrane::SideChain (&chains)[2],
                                 const MembraneSideData (&sides)[2],
                                 const membrane::SideLoad (&loads)[2])
{
  if (!fp_) return; // not rank 0
  std::fprintf(fp_, "ITEM: TIMESTEP\n" BIGINT_FORMAT "\n", step);
  for (int k = membrane::LEFT; k <= membrane::RIGHT; k++)
    if (chains[k].active)
      membrane::write_polyline_side(fp_, membrane::side_name(k), loads[k].polyline,
                                    sides[k].chain_disks, loads[k].forces);
  std::fflush(fp_);
}
