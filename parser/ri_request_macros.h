// The preprocessor side of parser/ri_requests.def: what one argument of a row becomes, and how
// a consumer walks a row's arguments.
//
// Each argument of a row becomes one element (Kind, name, "what") of a preprocessor sequence,
// e.g. (RiInt, xres, "xres")(RiInt, yres, "yres"). A consumer expands a sequence with
//   DARC_RI_PARAMS(seq)  ->  RiInt::param xres, RiInt::param yres,      (a parameter list)
//   DARC_RI_TYPES(seq)   ->  RiInt::param, RiInt::param,                (the same, unnamed)
//   DARC_RI_NAMES(seq)   ->  xres, yres,                                (an argument list)
//   DARC_RI_EACH(seq)    ->  DARC_RI_ON_ARG(RiInt, xres, "xres") ...    (DARC_RI_ON_ARG: the consumer's)
// Every form but DARC_RI_EACH ends in a comma, so that `const SourceLoc& loc` follows it.
// The walk uses the usual alternating pair of macros (A expands to its element and the name of
// B, which takes the next element, and so on); the name left after the last element is pasted
// with _END into a macro that expands to nothing.
#pragma once

#include "parser/ri_arg_kinds.h"

namespace darc {
// A row's shape: a request on its own line, or one that opens or closes a block (written
// indented by RibWriter). The names are the row's tokens.
enum class RequestShape { line, open, close };
}  // namespace darc

#define DARC_RI_ARG(Kind, name, what) (Kind, name, what)
#define DARC_RI_ARG2(a, b, what) (RiNumbers<2>, a, what)(RiNumbersNext, b, what)
#define DARC_RI_ARG3(a, b, c, what) (RiNumbers<3>, a, what)(RiNumbersNext, b, what)(RiNumbersNext, c, what)
#define DARC_RI_ARG4(a, b, c, d, what) \
  (RiNumbers<4>, a, what)(RiNumbersNext, b, what)(RiNumbersNext, c, what)(RiNumbersNext, d, what)

#define DARC_RI_CAT(a, b) DARC_RI_CAT_(a, b)
#define DARC_RI_CAT_(a, b) a##b
// What an element emits is deferred by one scan (the macro's name, then an empty macro, then its
// arguments): the commas and calls appear only after the pasting of _END, which must see the
// walk's output as one argument.
#define DARC_RI_EMPTY()
#define DARC_RI_COMMA() ,
#define DARC_RI_LATER(macro) macro DARC_RI_EMPTY()

#define DARC_RI_PARAMS(seq) DARC_RI_CAT(DARC_RI_PARAMS_A seq, _END)
#define DARC_RI_PARAMS_A(Kind, name, what) Kind::param name DARC_RI_LATER(DARC_RI_COMMA)() DARC_RI_PARAMS_B
#define DARC_RI_PARAMS_B(Kind, name, what) Kind::param name DARC_RI_LATER(DARC_RI_COMMA)() DARC_RI_PARAMS_A
#define DARC_RI_PARAMS_A_END
#define DARC_RI_PARAMS_B_END

#define DARC_RI_TYPES(seq) DARC_RI_CAT(DARC_RI_TYPES_A seq, _END)
#define DARC_RI_TYPES_A(Kind, name, what) Kind::param DARC_RI_LATER(DARC_RI_COMMA)() DARC_RI_TYPES_B
#define DARC_RI_TYPES_B(Kind, name, what) Kind::param DARC_RI_LATER(DARC_RI_COMMA)() DARC_RI_TYPES_A
#define DARC_RI_TYPES_A_END
#define DARC_RI_TYPES_B_END

#define DARC_RI_NAMES(seq) DARC_RI_CAT(DARC_RI_NAMES_A seq, _END)
#define DARC_RI_NAMES_A(Kind, name, what) name DARC_RI_LATER(DARC_RI_COMMA)() DARC_RI_NAMES_B
#define DARC_RI_NAMES_B(Kind, name, what) name DARC_RI_LATER(DARC_RI_COMMA)() DARC_RI_NAMES_A
#define DARC_RI_NAMES_A_END
#define DARC_RI_NAMES_B_END

#define DARC_RI_EACH(seq) DARC_RI_CAT(DARC_RI_EACH_A seq, _END)
#define DARC_RI_EACH_A(Kind, name, what) DARC_RI_LATER(DARC_RI_ON_ARG)(Kind, name, what) DARC_RI_EACH_B
#define DARC_RI_EACH_B(Kind, name, what) DARC_RI_LATER(DARC_RI_ON_ARG)(Kind, name, what) DARC_RI_EACH_A
#define DARC_RI_EACH_A_END
#define DARC_RI_EACH_B_END

// Rows by how they are read: DARC_RI_IF_GENERIC_<reading>(code) keeps `code` for the rows whose
// reading, writing and recording follow from the list (`table` and `parser`) and drops it for the
// `special` ones; DARC_RI_IF_TABLE_<reading>(code) keeps it for `table` rows only.
#define DARC_RI_IF_GENERIC_table(...) __VA_ARGS__
#define DARC_RI_IF_GENERIC_parser(...) __VA_ARGS__
#define DARC_RI_IF_GENERIC_special(...)
#define DARC_RI_IF_TABLE_table(...) __VA_ARGS__
#define DARC_RI_IF_TABLE_parser(...)
#define DARC_RI_IF_TABLE_special(...)
