#!/usr/bin/python3
"""Resume an interrupted shear run (run.sh --paper); liggghts_membrane.resume.

    resume_shear.py start OUT WALLS   print the restart file to resume from (nothing if none),
                                      after splicing a previous part and cutting OUT* there
    resume_shear.py finish OUT        splice the resumed part OUT.part* into OUT*
    resume_shear.py clean OUT         remove the restart files of a finished run
"""
import sys

from liggghts_membrane import resume

if __name__ == "__main__":
    if len(sys.argv) < 3 or sys.argv[1] not in ("start", "finish", "clean") or \
            (sys.argv[1] == "start") != (len(sys.argv) == 4):
        sys.exit(__doc__)
    command, out = sys.argv[1], sys.argv[2]
    if command == "start":
        restart = resume.start_resume(out, sys.argv[3])
        if restart:
            print(restart)
    elif command == "finish":
        resume.finish_part(out)
    else:
        resume.remove_restarts(out)
