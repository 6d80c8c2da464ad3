#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <contact_fem/core/parameters.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace contact_fem
{
  namespace
  {
    std::string
    trim(const std::string &s)
    {
      return Utilities::trim(s);
    }
  } // namespace

  std::string
  number_problem(const std::string &text, double &value)
  {
    const std::string number = trim(text);
    char             *end    = nullptr;
    errno                    = 0;
    value                    = std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size())
      return "is not a number";
    if (!std::isfinite(value))
      return "is not finite";
    // strtod() reports both overflow and underflow (a subnormal result) as
    // ERANGE.
    if (errno == ERANGE || (value != 0. && !std::isnormal(value)))
      return std::abs(value) >= 1. ?
               "is beyond the largest double (1.8e308)" :
               "is below the smallest normal double (2.2e-308), where only a few digits "
               "are kept";
    return "";
  }


  std::string
  user_message(const std::exception &e)
  {
    std::string       text = e.what();
    const std::string key  = "Additional information:";
    const auto        pos  = text.find(key);
    // deal.II's generic assertions explain nothing under "Additional
    // information"; their violated condition says what failed.
    const std::string condition = "The violated condition was:";
    const auto        at        = text.find(condition);
    const bool        generic   = text.find("which is used in many places") != std::string::npos;
    if (generic && at != std::string::npos && pos != std::string::npos && at < pos)
      text =
        "violated condition: " + text.substr(at + condition.size(), pos - at - condition.size());
    else if (pos != std::string::npos)
      {
        text           = text.substr(pos + key.size());
        const auto end = text.find("Stacktrace:");
        if (end != std::string::npos)
          text = text.substr(0, end);
      }
    // Collapse the line breaks and indentation of deal.II's formatting.
    std::string result;
    bool        space = false;
    for (const char c : text)
      if (c == '\n' || c == ' ' || c == '\t')
        space = !result.empty();
      else
        {
          if (space)
            result += ' ';
          result += c;
          space = false;
        }
    while (!result.empty() && result.back() == '-')
      result.pop_back();
    // deal.II's message for an unknown subsection lacks the '>' after the
    // file name and does not say where the names are listed.
    const std::regex no_subsection(
      "^Line <([0-9]+)> of file <(.*): There is no such subsection to be entered: (.*)$");
    if (std::smatch match; std::regex_match(result, match, no_subsection))
      {
        // deal.II joins the nested names by '.'; the input's keys use '/'.
        std::string path = match[3].str();
        std::replace(path.begin(), path.end(), '.', '/');
        result = "Line <" + match[1].str() + "> of file <" + match[2].str() +
                 ">: no subsection '" + path +
                 "' is declared (--print-parameters lists every subsection and key).";
      }
    // Trilinos' own code says nothing to a user; the one seen in practice
    // (error 2 from a sum into a matrix) is an entry outside the sparsity
    // pattern, a coupling the program did not foresee: a defect to report.
    if (result.find("occurred while calling a Trilinos function") != std::string::npos)
      result = "internal error: " + result +
               (result.find("error number 2 ") != std::string::npos ?
                  " (from the assembly: an entry outside the matrix's sparsity pattern, a "
                  "coupling the program did not foresee)" :
                  "") +
               ". Please report it with the parameter file";
    // A message quotes what the user wrote: bounded, whatever its length.
    constexpr std::size_t longest = 2000;
    if (result.size() > longest)
      result = result.substr(0, longest) + "... (the message continues for " +
               std::to_string(result.size() - longest) + " characters)";
    return result;
  }

  std::string
  excerpt(const std::string &value)
  {
    constexpr std::size_t shown = 60;
    if (value.size() <= shown + 20)
      return value;
    return value.substr(0, shown) + "... (" + std::to_string(value.size()) + " characters)";
  }

  void
  check_expression(const std::string &expression, const unsigned int dim, const std::string &key)
  {
    // deal.II adds rand() and rand_seed() to muparser: a load or a
    // displacement drawn at random makes a run unrepeatable.
    static const std::regex random_function("(^|[^A-Za-z0-9_])(rand|rand_seed|rnd)\\s*\\(");
    AssertThrow(!std::regex_search(expression, random_function),
                ExcMessage(key + ": '" + excerpt(expression) +
                           "' calls a random-number function (rand, rand_seed): two runs of "
                           "one scene would differ; use a deterministic expression."));
    // muparser's own limit (MaxLenExpression of muparser 2.3).
    constexpr std::size_t longest = 19999;
    AssertThrow(expression.size() <= longest,
                ExcMessage(key + ": '" + excerpt(expression) + "' is longer than the " +
                           std::to_string(longest) +
                           " characters the expression parser (muparser) takes."));
    const std::string variables = dim == 2 ? "x,y,t" : "x,y,z,t";
    // muparser takes "a, b" as a list of results and evaluates to the last:
    // "1: t, 3" would be a pressure of 3. A scalar is one expression (commas
    // only between the arguments of a function, as in min(t, 1)).
    unsigned int pieces = 1;
    int          depth  = 0;
    for (const char c : expression)
      {
        depth += c == '(' ? 1 : c == ')' ? -1 : 0;
        pieces += c == ',' && depth == 0;
      }
    AssertThrow(pieces == 1,
                ExcMessage(key + ": '" + excerpt(expression) + "' is " + std::to_string(pieces) +
                           " comma-separated expressions; expected one expression of " +
                           variables +
                           " (commas separate only the arguments of a function, as in min(t, "
                           "1); the expression parser would take the last one alone)."));
    // deal.II prints muparser's error, the whole expression included, to
    // std::cerr: caught here, and only its reason is quoted.
    std::ostringstream printed;
    std::streambuf    *cerr_buffer = std::cerr.rdbuf(printed.rdbuf());
    bool               valid       = true;
    try
      {
        if (dim == 2)
          {
            FunctionParser<2> f(1);
            f.initialize(variables, expression, {}, true);
            f.value(Point<2>());
          }
        else
          {
            FunctionParser<3> f(1);
            f.initialize(variables, expression, {}, true);
            f.value(Point<3>());
          }
      }
    catch (...)
      {
        valid = false;
      }
    std::cerr.rdbuf(cerr_buffer);
    const std::string text   = printed.str();
    const auto        start  = text.find("Message:");
    const auto        open   = text.find('<', start);
    const auto        close  = text.find('>', open);
    std::string       reason = start != std::string::npos && close != std::string::npos ?
                                 text.substr(open + 1, close - open - 1) :
                                 "";
    while (!reason.empty() && (reason.back() == '.' || reason.back() == ' '))
      reason.pop_back();
    reason = reason.empty() ? reason : " (" + excerpt(reason) + ")";
    AssertThrow(valid, ExcMessage(key + ": '" + excerpt(expression) +
                                  "' is not a valid expression of " + variables + reason + "."));
  }

  std::vector<double>
  parse_number_list(const std::string &text, const std::string &key, const std::string &expected)
  {
    std::vector<double>            values;
    const std::vector<std::string> entries = Utilities::split_string_list(text, ',');
    for (unsigned int i = 0; i < entries.size(); ++i)
      {
        double            value   = 0.;
        const std::string problem = number_problem(entries[i], value);
        AssertThrow(problem.empty(), ExcMessage(key + ": entry " + std::to_string(i + 1) + ", '" +
                                                excerpt(entries[i]) + "', " + problem +
                                                "; expected " + expected + "."));
        values.push_back(value);
      }
    return values;
  }

  std::vector<std::pair<std::string, std::string>>
  split_key_value_list(const std::string &text, const std::string &key)
  {
    std::vector<std::pair<std::string, std::string>> result;
    for (const std::string &item : Utilities::split_string_list(text, ';'))
      {
        if (trim(item).empty())
          continue;
        const auto colon = item.find(':');
        AssertThrow(colon != std::string::npos, ExcMessage(key + ": entry '" + excerpt(item) +
                                                           "' is not of the form 'id: value'."));
        result.emplace_back(trim(item.substr(0, colon)), trim(item.substr(colon + 1)));
      }
    return result;
  }

  types::boundary_id
  parse_boundary_id(const std::string &text, const std::string &key)
  {
    int id = -1;
    try
      {
        std::size_t pos = 0;
        id              = std::stoi(text, &pos);
        if (pos != text.size())
          id = -1;
      }
    catch (...)
      {
        id = -1;
      }
    AssertThrow(id >= 0 && id < 255,
                ExcMessage(key + ": '" + excerpt(text) +
                           "' is not a boundary id (an integer from 0 to 254)."));
    return static_cast<types::boundary_id>(id);
  }

  BodyPoint
  parse_body_point(const std::string &text, const unsigned int dim, const std::string &key)
  {
    const auto at = text.find('@');
    BodyPoint  point;
    bool       valid = at != std::string::npos;
    if (valid)
      try
        {
          const int id = Utilities::string_to_int(trim(text.substr(0, at)));
          for (const std::string &coordinate : Utilities::split_string_list(text.substr(at + 1)))
            {
              // A coordinate that is a number but not a usable double is
              // reported as such, not as a malformed entry.
              double            value   = 0.;
              const std::string problem = number_problem(coordinate, value);
              AssertThrow(problem.empty() || problem == "is not a number",
                          ExcMessage(key + ": '" + trim(text) + "': coordinate '" + coordinate +
                                     "' " + problem + "; expected a normal double or 0."));
              valid = valid && problem.empty();
              point.coordinates.push_back(value);
            }
          valid             = valid && id >= 0 && id < 255 && point.coordinates.size() == dim;
          point.material_id = static_cast<types::material_id>(id);
        }
      catch (const ExcMessage &)
        {
          throw;
        }
      catch (...)
        {
          valid = false;
        }
    AssertThrow(valid,
                ExcMessage(key + ": '" + trim(text) + "' is not of the form 'material id @ x, y" +
                           (dim == 3 ? ", z" : "") + "'."));
    return point;
  }

  std::string
  to_string(const BodyPoint &point)
  {
    // 10 digits: the coordinates as written (1.001, not 1.0009999999999999).
    std::ostringstream text;
    text << static_cast<unsigned int>(point.material_id) << " @ " << std::setprecision(10);
    for (unsigned int d = 0; d < point.coordinates.size(); ++d)
      text << (d > 0 ? ", " : "") << point.coordinates[d];
    return text.str();
  }

  std::string
  not_set_help(const bool required)
  {
    return std::string(" Not set in the input: the built-in scene's own value (listed "
                       "under Geometry/Type); ") +
           (required ? "a mesh-file scene must set it." :
                       "none for a mesh file. Set it empty for none.");
  }

  bool
  is_set(const ParameterHandler &prm, const std::string &path)
  {
    // ParameterHandler's names: '.' between subsections, every character
    // but letters and digits as '_' and two hex digits.
    std::string mangled;
    for (const char c : path)
      if (c == '/')
        mangled += '.';
      else if (std::isalnum(static_cast<unsigned char>(c)))
        mangled += c;
      else
        {
          const char *hex = "0123456789abcdef";
          const auto  u   = static_cast<unsigned char>(c);
          mangled += {'_', hex[u / 16], hex[u % 16]};
        }
    return prm.get_entries_wrongly_not_set().count(mangled) == 0;
  }
} // namespace contact_fem
