#ifndef LIGGGHTS_MEMBRANE_STYLE_ARGS_H
#define LIGGGHTS_MEMBRANE_STYLE_ARGS_H

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <string>

#include "lammps.h"

#include "number_text.h"
#include "style_error.h"

// The keyword/value arguments of a style, walked in order, with one form for
// every message of our styles (doc/messages.md):
//
//   <Kind> <style> (id <ID>): keyword '<key>' = <value>: <what is wrong>; <usage or what to do>
//   <Kind> <style> (id <ID>): keyword '<key>' needs a value: <usage>
//   <Kind> <style> (id <ID>): keyword '<key>' is required: <usage>
//   <Kind> <style> (id <ID>): unknown keyword '<key>'; keywords: <list>
//
// `prefix` is what style_prefix() (style_error.h) makes, "Compute fabric (id
// fab): ", or any other prefix the style gives; `usage` says what the value is
// ("band W: a length in distance units, default 4 x D50"). Errors are raised
// with style_error().

// "keyword 'key' = value: problem", for style_error(lmp, prefix, ...)
inline std::string keyword_text(const std::string &key, const std::string &value,
                                const std::string &problem)
{
  return "keyword '" + key + "' = " + (value.empty() ? "''" : value) + ": " + problem;
}

class StyleArgs {
 public:
  StyleArgs(LAMMPS_NS::LAMMPS *lmp, std::string prefix, int narg, char **arg, int first)
    : lmp_(lmp), prefix_(std::move(prefix)), narg_(narg), arg_(arg), next_(first)
  {
  }

  bool more() const { return next_ < narg_; }

  // the next keyword; its value(s) follow
  const std::string &keyword()
  {
    key_ = arg_[next_++];
    return key_;
  }

  // the next word as this keyword's value
  const char *value(const std::string &usage)
  {
    if (next_ >= narg_) fail("keyword '" + key_ + "' needs a value: " + usage);
    value_ = arg_[next_++];
    return value_;
  }

  double positive(const std::string &usage)
  {
    const double v = number(usage);
    if (!(v > 0.0)) bad("must be a positive number", usage);
    return v;
  }

  double non_negative(const std::string &usage)
  {
    const double v = number(usage);
    if (!(v >= 0.0)) bad("must be a number >= 0", usage);
    return v;
  }

  // a finite number
  double number(const std::string &usage)
  {
    const char *text = value(usage);
    char *end = nullptr;
    const double v = strtod(text, &end);
    if (*text == '\0' || *end != '\0') bad("is not a number", usage);
    if (!std::isfinite(v)) bad("must be finite", usage);
    return v;
  }

  long integer(long lo, long hi, const std::string &usage)
  {
    return to_integer(value(usage), lo, hi, usage);
  }

  // the current value `text` (already taken with value()) as an integer
  long to_integer(const char *text, long lo, long hi, const std::string &usage)
  {
    char *end = nullptr;
    errno = 0;
    const long v = strtol(text, &end, 10);
    if (*text == '\0' || *end != '\0') bad("is not an integer", usage);
    if (errno == ERANGE) bad("is out of range", usage);
    if (v < lo || v > hi)
      bad("must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi), usage);
    return v;
  }

  bool yes_no(const std::string &usage) { return choice({"yes", "no"}, usage) == 0; }

  // the index in `words` of the next value: "must be a, b or c" otherwise
  int choice(std::initializer_list<const char *> words, const std::string &usage)
  {
    const std::string v = value(usage);
    int index = 0;
    std::string list;
    for (const char *w : words) {
      if (v == w) return index;
      list += std::string(index == 0                                    ? ""
                          : index + 1 == static_cast<int>(words.size()) ? " or "
                                                                        : ", ") +
              w;
      index++;
    }
    bad("must be " + list, usage);
  }

  // the current value is wrong: "<prefix>keyword 'k' = v: problem; usage"
  [[noreturn]] void bad(const std::string &problem, const std::string &usage) const
  {
    fail(keyword_text(key_, value_, problem + "; " + usage));
  }

  // a keyword this style knows but refuses here; `why` says why and what instead
  [[noreturn]] void refused(const std::string &why) const { fail("keyword '" + key_ + "' " + why); }

  [[noreturn]] void unknown(const std::string &keywords) const
  {
    fail("unknown keyword '" + key_ + "'; keywords: " + keywords);
  }

  [[noreturn]] void required(const std::string &key, const std::string &usage) const
  {
    fail("keyword '" + key + "' is required: " + usage);
  }

  const char *current_value() const { return value_; }

 private:
  // every rank reads the same arguments: every rank stops
  [[noreturn]] void fail(const std::string &text) const { style_error(lmp_, prefix_, text); }

  LAMMPS_NS::LAMMPS *lmp_;
  std::string prefix_;
  int narg_;
  char **arg_;
  int next_;
  std::string key_;
  const char *value_ = "";
};

#endif
