#ifndef LIGGGHTS_MEMBRANE_SCALAR_INPUT_H
#define LIGGGHTS_MEMBRANE_SCALAR_INPUT_H

#include <cmath>
#include <cstdlib>
#include <string>

#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include "style_args.h"
#include "style_error.h"

// A style argument given as a number or as an equal-style variable v_name
// (pressures, platen positions, strain rates). Errors name the style through
// `prefix` (style_prefix(), style_error.h) and the keyword through `name`, in
// the form of style_args.h. A variable has one value on every rank (equal-style),
// so every rank takes the same decision.
class ScalarInput {
 public:
  enum class Sign { Any, NonNegative, Positive };

  // the next value of `args`: a number (finite, of the sign asked) or v_name;
  // a variable's sign is checked when it is evaluated (evaluate_checked)
  void read(StyleArgs &args, Sign sign, const std::string &usage)
  {
    *this = ScalarInput(); // a repeated keyword takes its last value
    const std::string text = args.value(usage);
    if (text.compare(0, 2, "v_") == 0) {
      if (text.size() == 2) args.bad("names no variable", usage);
      varname_ = text.substr(2);
      return;
    }
    char *end = nullptr;
    value_ = strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0') args.bad("is neither a number nor v_name", usage);
    if (!std::isfinite(value_)) args.bad("must be finite", usage);
    if (sign == Sign::Positive && !(value_ > 0.0)) args.bad("must be a positive number", usage);
    if (sign == Sign::NonNegative && !(value_ >= 0.0)) args.bad("must be a number >= 0", usage);
  }

  // finds the variable (input scripts may define it after the style)
  void init(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix, const char *name)
  {
    if (varname_.empty()) return;
    ivar_ = lmp->input->variable->find(const_cast<char *>(varname_.c_str()));
    if (ivar_ < 0)
      style_error(lmp, prefix,
                  keyword_text(name, "v_" + varname_,
                               "variable '" + varname_ + "' does not exist; define it (variable " +
                                   varname_ + " equal ...) before the run"));
    if (!lmp->input->variable->equalstyle(ivar_))
      style_error(
          lmp, prefix,
          keyword_text(name, "v_" + varname_,
                       "variable '" + varname_ +
                           "' is not equal-style; use an equal-style variable (one number)"));
  }

  // computes referenced by the variable are invoked on demand, as fix ave/time does
  double evaluate(LAMMPS_NS::LAMMPS *lmp) const
  {
    if (varname_.empty()) return value_;
    lmp->modify->clearstep_compute();
    const double v = lmp->input->variable->compute_equal(ivar_);
    lmp->modify->addstep_compute(lmp->update->ntimestep + 1);
    return v;
  }

  // the value, which must be finite (and >= 0 with `non_negative`): a variable
  // that turns NaN, inf or negative mid-run stops the run with the step
  double evaluate_checked(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix, const char *name,
                          bool non_negative) const
  {
    return checked(lmp, prefix, name, non_negative, evaluate(lmp));
  }

  // `v` (this input's value, evaluated elsewhere), checked as evaluate_checked does
  double checked(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix, const char *name,
                 bool non_negative, double v) const
  {
    if (!std::isfinite(v) || (non_negative && !(v >= 0.0)))
      style_error(lmp, prefix,
                  keyword_text(name, text(),
                               std::string("is ") + number_text(v) + " at step " +
                                   std::to_string(lmp->update->ntimestep) + "; it must be " +
                                   (non_negative ? "a finite number >= 0" : "finite")));
    return v;
  }

  bool is_variable() const { return !varname_.empty(); }
  // as the user wrote it: the number or v_name
  std::string text() const { return is_variable() ? "v_" + varname_ : number_text(value_); }

 private:
  double value_ = 0.0;
  std::string varname_;
  int ivar_ = -1;
};

#endif
