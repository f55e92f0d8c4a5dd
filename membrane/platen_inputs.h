#ifndef LIGGGHTS_MEMBRANE_PLATEN_INPUTS_H
#define LIGGGHTS_MEMBRANE_PLATEN_INPUTS_H

#include <string>
#include <utility>

#include "scalar_input.h"
#include "style_args.h"

// The keywords both membranes take and require: the confining pressure and the two
// platen surfaces (ylo/yhi in 2D, zlo/zhi in 3D), each a number or v_name.
class PlatenInputs {
 public:
  ScalarInput pressure, lo, hi;
  const std::string lo_key, hi_key;

  PlatenInputs(std::string lo_keyword, std::string hi_keyword, std::string use_pressure,
               std::string use_lo, std::string use_hi)
    : lo_key(std::move(lo_keyword)), hi_key(std::move(hi_keyword)),
      use_pressure_(std::move(use_pressure)), use_lo_(std::move(use_lo)), use_hi_(std::move(use_hi))
  {
  }

  // reads the value of `key` when it is one of the three (true); false for any other
  bool read(StyleArgs &args, const std::string &key)
  {
    if (key == "pressure") {
      pressure.read(args, ScalarInput::Sign::NonNegative, use_pressure_);
      given_[0] = true;
    } else if (key == lo_key) {
      lo.read(args, ScalarInput::Sign::Any, use_lo_);
      given_[1] = true;
    } else if (key == hi_key) {
      hi.read(args, ScalarInput::Sign::Any, use_hi_);
      given_[2] = true;
    } else {
      return false;
    }
    return true;
  }

  // after the last keyword: an error for the first of them not given
  void require(StyleArgs &args) const
  {
    if (!given_[0]) args.required("pressure", use_pressure_);
    if (!given_[1]) args.required(lo_key, use_lo_);
    if (!given_[2]) args.required(hi_key, use_hi_);
  }

  // finds their variables (init of the style)
  void init(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix)
  {
    pressure.init(lmp, prefix, "pressure");
    lo.init(lmp, prefix, lo_key.c_str());
    hi.init(lmp, prefix, hi_key.c_str());
  }

 private:
  const std::string use_pressure_, use_lo_, use_hi_;
  bool given_[3] = {false, false, false};
};

#endif
