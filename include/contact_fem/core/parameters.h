// The run parameters of a scene that are not owned by a component class:
// boundary conditions, load stepping, contact, Newton and output settings.
#ifndef contact_fem_parameters_h
#define contact_fem_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <exception>

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /// A mesh vertex of one body, written 'material id @ x, y(, z)'.
  struct BodyPoint
  {
    types::material_id  material_id = 0;
    std::vector<double> coordinates;
  };

  /// Parses 'material id @ x, y(, z)'; throws naming @p key otherwise.
  BodyPoint
  parse_body_point(const std::string &text, const unsigned int dim, const std::string &key);

  /// The text 'material id @ x, y(, z)' of @p point (for messages and output).
  std::string
  to_string(const BodyPoint &point);

  /// Why @p text is not a usable double, or an empty string if it is one
  /// (then stored in @p value): not a number, not finite, or outside the
  /// normal range of double precision. strtod() turns '1e-320' into a
  /// subnormal that keeps only a few digits, and deal.II's conversion then
  /// fails with a message that names neither key nor entry.
  std::string
  number_problem(const std::string &text, double &value);

  /// The comma-separated numbers of @p text; throws naming @p key, the
  /// entry and what was expected (@p expected, e.g. "a positive normal
  /// double") if one is not a usable double (number_problem()).
  std::vector<double>
  parse_number_list(const std::string &text, const std::string &key, const std::string &expected);

  /// Parses "a: b; c: d" style lists; throws naming @p key on malformed input.
  std::vector<std::pair<std::string, std::string>>
  split_key_value_list(const std::string &text, const std::string &key);

  /// The message of @p e without deal.II's source location and stack trace
  /// (users need its "Additional information" only), on one line and
  /// bounded in length.
  std::string
  user_message(const std::exception &e);

  /// @p value itself if short, else its start and its length: messages
  /// quote a bounded excerpt of what the user wrote, never a whole long
  /// value (a 10,000-character expression would flood the log).
  std::string
  excerpt(const std::string &value);

  /// Checks that @p expression is a valid, deterministic muparser expression
  /// of x, y, (z,) t (@p dim 2 or 3); throws naming @p key otherwise.
  /// rand() and rand_seed() are refused: two runs of one scene would
  /// differ.
  void
  check_expression(const std::string &expression, const unsigned int dim, const std::string &key);

  /// Parses a boundary id; throws naming @p key if it is not in 0..254.
  types::boundary_id
  parse_boundary_id(const std::string &text, const std::string &key);

  /// The sentence ending the documentation of a key that the built-in
  /// scenes fill in when the input does not set it (declared with
  /// has_to_be_set, so that "not set" differs from "set empty"); @p required
  /// for a key that a mesh-file scene must set.
  std::string
  not_set_help(const bool required);

  /// Whether the input set @p path ("Subsection/Key", declared with
  /// has_to_be_set): from the file, an included file or --set, even to an
  /// empty value.
  bool
  is_set(const ParameterHandler &prm, const std::string &path);
} // namespace contact_fem

#endif
