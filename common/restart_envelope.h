#ifndef LIGGGHTS_MEMBRANE_RESTART_ENVELOPE_H
#define LIGGGHTS_MEMBRANE_RESTART_ENVELOPE_H

#include <cstddef>
#include <cstdio>
#include <vector>

#include "comm.h"
#include "lammps.h"

#include "restart_record.h"

// The one way a style stores its global state in a LIGGGHTS restart file: a
// record of restart_record.h (magic, version, length, fields) in LIGGGHTS'
// envelope (an int byte count, then the doubles). Files written before this
// header read alike: it writes the same bytes the styles wrote by hand.
//
//   void FixX::write_restart(FILE *fp)
//   {
//     RestartRecordWriter out(MAGIC, VERSION);
//     out.put(...);
//     write_restart_record(lmp, fp, out.finish());
//   }
//   void FixX::restart(char *raw)
//   {
//     RestartRecordReader in = read_restart_record(raw, MAGIC, VERSION);
//     ... = in.get();
//     if (!in.finished()) style_error(lmp, prefix, "... " + in.error() + "; ...");
//   }

// Writes `record` (RestartRecordWriter::finish()) into the restart file. Call it
// on every rank: only rank 0 holds the file (Modify::write_restart opens it there).
inline void write_restart_record(LAMMPS_NS::LAMMPS *lmp, std::FILE *fp,
                                 const std::vector<double> &record)
{
  if (lmp->comm->me == 0) write_record_bytes(fp, record);
}

// reading: read_restart_record() of restart_record.h (no LIGGGHTS needed)

#endif
