// contact_fem: runs one scene described by a ParameterHandler file.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <contact_fem/core/interruption.h>
#include <contact_fem/core/parameters.h>
#include <contact_fem/simulator/contact_problem.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;

  const char *usage =
    "Usage: contact_fem [options] SCENE.prm\n"
    "\n"
    "Solves the contact scene described by SCENE.prm and writes its results\n"
    "(summary.json, log.txt, pressure profile, VTU) to the output directory.\n"
    "\n"
    "Options:\n"
    "  --help                     print this message and exit\n"
    "  --print-parameters         print every parameter with its default, its\n"
    "                             allowed values and its documentation, and exit\n"
    "  --set \"Sub/Key=value\"      override one parameter of the file (repeatable;\n"
    "                             subsections separated by '/')\n"
    "  --output-directory DIR     put every output file of the run under DIR\n"
    "  --validate                 read and check the file and the scene it\n"
    "                             builds (mesh, supports, contact set-up: every\n"
    "                             check up to the first solve), then exit\n"
    "\n"
    "Exit codes: 0 success, 1 bad input, 2 the solver failed or the memory ran\n"
    "short (the results of the last converged load step or cycle are written\n"
    "and marked as such), 128+N stopped by signal N (SIGINT 130, SIGTERM 143;\n"
    "summary.json says \"interrupted\").\n";

  struct CommandLine
  {
    std::string                                      prm_file;
    std::vector<std::pair<std::string, std::string>> overrides;
    std::string                                      output_directory;
    bool help = false, print_parameters = false, validate = false;
  };

  CommandLine
  parse_command_line(int argc, char **argv)
  {
    CommandLine cl;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg  = argv[i];
        auto              next = [&](const std::string &option) {
          if (i + 1 >= argc)
            throw std::runtime_error("option " + option + " needs a value.");
          return std::string(argv[++i]);
        };
        if (arg == "--help" || arg == "-h")
          cl.help = true;
        else if (arg == "--print-parameters")
          cl.print_parameters = true;
        else if (arg == "--validate")
          cl.validate = true;
        else if (arg == "--set")
          {
            const std::string assignment = next(arg);
            const auto        eq         = assignment.find('=');
            if (eq == std::string::npos)
              throw std::runtime_error("--set \"" + contact_fem::excerpt(assignment) +
                                       "\": expected \"Subsection/Key=value\" (no '=').");
            cl.overrides.emplace_back(assignment.substr(0, eq), assignment.substr(eq + 1));
          }
        else if (arg == "--output-directory")
          {
            cl.output_directory = next(arg);
            // Empty, it would be ignored: the results would go elsewhere.
            if (Utilities::trim(cl.output_directory).empty())
              throw std::runtime_error("option --output-directory: got an empty path; expected "
                                       "the directory for the results.");
          }
        else if (!arg.empty() && arg[0] == '-')
          throw std::runtime_error("unknown option '" + arg + "' (see --help).");
        else if (cl.prm_file.empty())
          cl.prm_file = arg;
        else
          throw std::runtime_error("more than one parameter file given ('" + cl.prm_file +
                                   "' and '" + arg + "').");
      }
    return cl;
  }

  /// Whether a line of a .prm file may set something: not a comment, a
  /// blank line, 'subsection' or 'end' (malformed lines count, so that
  /// ParameterHandler reports them).
  bool
  is_setting(const std::string &line)
  {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string        first;
    words >> first;
    return !first.empty() && first != "subsection" && first != "end";
  }

  /// Throws naming @p file unless it is a regular file (or a link to one):
  /// a directory reads as an empty file, a FIFO or a device blocks for ever.
  void
  require_regular_file(const std::string &file, const std::string &what)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    const auto      status = fs::status(file, error);
    if (!fs::exists(status))
      throw std::runtime_error("cannot open " + what + " '" + file + "': it does not exist.");
    if (fs::is_directory(status))
      throw std::runtime_error(what + " '" + file + "' is a directory; expected a .prm file.");
    if (!fs::is_regular_file(status))
      throw std::runtime_error(what + " '" + file +
                               "' is not a regular file (a FIFO, socket or device); expected "
                               "a .prm file.");
  }

  /// The file named by a ParameterHandler 'include' line (deal.II: the
  /// line, without its comment, starts with "include " or "INCLUDE "), or
  /// an empty string.
  std::string
  included_file(const std::string &line)
  {
    const std::string text = Utilities::trim(line.substr(0, line.find('#')));
    if (text.compare(0, 8, "include ") != 0 && text.compare(0, 8, "INCLUDE ") != 0)
      return "";
    return Utilities::trim(text.substr(8));
  }

  /// Refuses a key set twice in one .prm file, in the same subsection
  /// (entered once or twice): ParameterHandler keeps the last value without
  /// a word, so one of the two values the user wrote would be ignored. (A
  /// file may override what it includes: that is across files.)
  class DuplicateKeys
  {
  public:
    explicit DuplicateKeys(const std::string &file)
      : file(file)
    {}

    /// One logical line (continuations joined) that starts at @p number.
    void
    read(const std::string &line, const unsigned int number)
    {
      std::istringstream words(line.substr(0, line.find('#')));
      std::string        first;
      words >> first;
      if (first == "subsection")
        {
          std::string name;
          std::getline(words, name);
          path.push_back(Utilities::trim(name));
        }
      else if ((first == "end" || first == "END") && !path.empty())
        path.pop_back();
      else if (first == "set" || first == "SET")
        {
          std::string rest;
          std::getline(words, rest);
          const auto equals = rest.find('=');
          if (equals == std::string::npos)
            return; // malformed: ParameterHandler names the line
          std::string key;
          for (const std::string &section : path)
            key += section + "/";
          key += Utilities::trim(rest.substr(0, equals));
          const auto [where, inserted] = first_line.emplace(key, number);
          if (!inserted)
            throw std::runtime_error(
              "the parameter file '" + file + "', line " + std::to_string(number) + ": '" + key +
              "' is set a second time (first on line " + std::to_string(where->second) +
              "); only the last value would be used. Keep one of "
              "the two.");
        }
    }

  private:
    const std::string                   file;
    std::vector<std::string>            path;
    std::map<std::string, unsigned int> first_line;
  };

  /// Follows the 'include' lines of a .prm file: every file must be a
  /// regular file and none may include itself, directly or through others
  /// (ParameterHandler would recurse until the stack overflows). Each file
  /// is checked for keys set twice.
  void
  check_includes(const std::string &file, std::vector<std::string> &chain)
  {
    std::error_code error;
    const auto      canonical = std::filesystem::weakly_canonical(file, error).string();
    chain.push_back(canonical);
    std::ifstream in(file);
    std::string   line;
    DuplicateKeys duplicates(file);
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        // A line ending in '\' goes on in the next one (ParameterHandler).
        const unsigned int start = number;
        std::string        next;
        const auto         continued = [](const std::string &text) {
          const std::string trimmed = Utilities::trim(text);
          return !trimmed.empty() && trimmed.back() == '\\';
        };
        while (continued(line) && std::getline(in, next))
          {
            line = Utilities::trim(line);
            line = line.substr(0, line.size() - 1) + " " + next;
            ++number;
          }
        duplicates.read(line, start);
        const std::string included = included_file(line);
        if (included.empty())
          continue;
        const std::string where = "the parameter file '" + file + "', line " +
                                  std::to_string(number) + ", 'include " + included + "'";
        require_regular_file(included, where + ": the included file");
        const auto again = std::filesystem::weakly_canonical(included, error).string();
        if (std::find(chain.begin(), chain.end(), again) != chain.end())
          throw std::runtime_error(where + ": includes a file that is already being read "
                                           "(an include cycle, which never ends).");
        check_includes(included, chain);
      }
    chain.pop_back();
  }

  /// Whether the scan of @p file (as ParameterHandler reads it: an
  /// included file continues in the subsection of its include line)
  /// reaches line @p target_line of @p target; @p path then holds the
  /// subsections open there.
  bool
  subsections_at(const std::string        &file,
                 const std::string        &target,
                 const unsigned int        target_line,
                 std::vector<std::string> &path)
  {
    std::error_code error;
    const bool      here = std::filesystem::weakly_canonical(file, error) ==
                      std::filesystem::weakly_canonical(target, error);
    std::ifstream in(file);
    std::string   line;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        if (here && number >= target_line)
          return true;
        std::istringstream words(line.substr(0, line.find('#')));
        std::string        first;
        words >> first;
        if (first == "subsection" || first == "SUBSECTION")
          {
            std::string name;
            std::getline(words, name);
            path.push_back(Utilities::trim(name));
          }
        else if ((first == "end" || first == "END") && !path.empty())
          path.pop_back();
        else if (const std::string included = included_file(line);
                 !included.empty() && subsections_at(included, target, target_line, path))
          return true;
      }
    return false;
  }

  /// The number of values set in @p tree (JSON or XML read by boost),
  /// without XML attributes and comments.
  unsigned int
  count_values(const boost::property_tree::ptree &tree)
  {
    unsigned int n = 0;
    for (const auto &[key, child] : tree)
      if (key != "<xmlattr>" && key != "<xmlcomment>")
        n += child.empty() ? !Utilities::trim(child.data()).empty() : count_values(child);
    return n;
  }

  /// Reads a JSON or XML parameter file as ParameterHandler will, so that
  /// a malformed one is named with its line, and one that sets nothing
  /// ("{}", "<ParameterHandler/>") is refused like an empty .prm.
  void
  check_structured_file(const std::string &file, const bool json)
  {
    boost::property_tree::ptree tree;
    try
      {
        if (json)
          boost::property_tree::read_json(file, tree);
        else
          boost::property_tree::read_xml(file, tree);
      }
    catch (const boost::property_tree::file_parser_error &e)
      {
        throw std::runtime_error("the parameter file '" + file + "', line " +
                                 std::to_string(e.line()) + ": " + e.message() +
                                 "; expected a parameter file in " + (json ? "JSON" : "XML") +
                                 " (deal.II's ParameterHandler format).");
      }
    if (count_values(tree) == 0)
      throw std::runtime_error("the parameter file '" + file +
                               "' sets no value (an empty file would run the default scene).");
  }

  /// Refuses a parameter file that is not a regular file or holds no
  /// settings: ParameterHandler reads both as an empty file and the run
  /// would solve the default scene as if asked to.
  void
  check_parameter_file(const std::string &file)
  {
    require_regular_file(file, "the parameter file");
    std::ifstream in(file);
    if (!in)
      throw std::runtime_error("cannot open the parameter file '" + file + "'.");
    const auto ends_with = [&](const std::string &suffix) {
      return file.size() >= suffix.size() &&
             file.compare(file.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    std::string line;
    bool        empty = true, settings = false;
    while (std::getline(in, line))
      {
        empty    = empty && line.find_first_not_of(" \t\r") == std::string::npos;
        settings = settings || is_setting(line);
      }
    if (empty)
      throw std::runtime_error("the parameter file '" + file +
                               "' is empty: it has no settings (an empty file would run "
                               "the default scene).");
    if (ends_with(".json") || ends_with(".xml"))
      return check_structured_file(file, ends_with(".json"));
    // ParameterHandler picks the format by the extension and would say only
    // "Unknown input file name extension", naming no file.
    if (!ends_with(".prm"))
      {
        const std::string name = file.substr(file.find_last_of('/') + 1);
        const auto        dot  = name.find_last_of('.');
        throw std::runtime_error(
          "the parameter file '" + file + "' " +
          (dot == std::string::npos ? std::string("has no extension") :
                                      "has the extension '" + name.substr(dot) + "'") +
          ": contact_fem reads a parameter file by its extension, .prm (or .json, .xml "
          "for those formats); rename it, e.g. to '" + name.substr(0, dot) + ".prm'.");
      }
    if (!settings)
      throw std::runtime_error("the parameter file '" + file +
                               "' has no settings, only comments or subsections (it would "
                               "run the default scene).");
    std::vector<std::string> chain;
    check_includes(file, chain);
  }

  /// Undoes ParameterHandler's name mangling ("_20" for a blank, ...).
  std::string
  demangle(const std::string &name)
  {
    std::string result;
    for (std::size_t i = 0; i < name.size(); ++i)
      if (name[i] == '_' && i + 2 < name.size() + 0 && std::isxdigit(name[i + 1]) &&
          std::isxdigit(name[i + 2]))
        {
          result += static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
          i += 2;
        }
      else
        result += name[i];
    return result;
  }

  /// Applies "A/B/Key=value" after checking that the subsections and the
  /// key are declared, so that a message names the option, the missing
  /// name or the expected value (ParameterHandler's own names an
  /// "<input string>").
  void
  apply_override(ParameterHandler                  &prm,
                 const boost::property_tree::ptree &declared,
                 const std::string                 &path,
                 const std::string                 &value)
  {
    const std::string        option = "--set \"" + contact_fem::excerpt(path + "=" + value) + "\"";
    std::vector<std::string> parts  = Utilities::split_string_list(path, '/');
    if (parts.empty() || std::any_of(parts.begin(), parts.end(), [](const std::string &p) {
          return p.empty();
        }))
      throw std::runtime_error(option + ": expected \"Subsection/Key=value\" (a key before "
                                        "'=', subsections separated by single '/').");
    const boost::property_tree::ptree *node  = &declared;
    std::string                        where = "at the top level";
    for (unsigned int i = 0; i < parts.size(); ++i)
      {
        const bool                         last  = i + 1 == parts.size();
        const boost::property_tree::ptree *found = nullptr;
        for (const auto &[key, child] : *node)
          if (demangle(key) == parts[i])
            found = &child;
        const bool is_key = found && found->count("value") && found->count("default_value");
        if (!found || is_key != last)
          throw std::runtime_error(
            option + ": " +
            (found ?
               "'" + parts[i] + "' is " +
                 (is_key ? "a key, not a subsection" : "a subsection, not a key") :
               "no " + std::string(last ? "key" : "subsection") + " '" + parts[i] + "' " + where) +
            " (--print-parameters lists every subsection and key).");
        node  = found;
        where = "in subsection '";
        for (unsigned int j = 0; j <= i; ++j)
          where += (j > 0 ? "/" : "") + parts[j];
        where += "'";
      }
    for (unsigned int i = 0; i + 1 < parts.size(); ++i)
      prm.enter_subsection(parts[i]);
    bool matched = true;
    try
      {
        prm.set(parts.back(), value);
      }
    catch (...)
      {
        matched = false;
      }
    for (unsigned int i = 0; i + 1 < parts.size(); ++i)
      prm.leave_subsection();
    if (!matched)
      throw std::runtime_error(option + ": '" + contact_fem::excerpt(value) +
                               "' is not a valid value; expected " +
                               node->get<std::string>("pattern_description") + ".");
  }

  /// The declared parameters with their defaults, patterns and
  /// documentation (ParameterHandler's JSON listing).
  boost::property_tree::ptree
  declared_parameters(const ParameterHandler &prm)
  {
    std::stringstream json;
    prm.print_parameters(json, ParameterHandler::JSON);
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(json, tree);
    return tree;
  }

  /// Whether @p node of the declared tree is a key (not a subsection).
  bool
  is_key(const boost::property_tree::ptree &node)
  {
    return node.count("value") && node.count("default_value");
  }

  /// The node of subsection @p section ("A/B"; "" the top level) of the
  /// declared tree @p declared; the deepest existing one if a part is
  /// missing.
  const boost::property_tree::ptree &
  subsection_node(const boost::property_tree::ptree &declared, const std::string &section)
  {
    const boost::property_tree::ptree *node = &declared;
    for (const std::string &part : Utilities::split_string_list(section, '/'))
      for (const auto &[key, child] : *node)
        if (demangle(key) == part)
          {
            node = &child;
            break;
          }
    return *node;
  }

  /// The paths ("A/B", "" for the top level) of the subsections that
  /// declare an entry named @p name, and whether each is a key.
  void
  find_entry(const boost::property_tree::ptree            &tree,
             const std::string                            &name,
             const std::string                            &path,
             std::vector<std::pair<std::string, bool>>    &found)
  {
    for (const auto &[key, child] : tree)
      {
        if (demangle(key) == name)
          found.emplace_back(path, is_key(child));
        if (!is_key(child) && !child.empty())
          find_entry(child, name, path + (path.empty() ? "" : "/") + demangle(key), found);
      }
  }

  /// Edits (insertions, deletions, substitutions) from @p a to @p b.
  std::size_t
  edit_distance(const std::string &a, const std::string &b)
  {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
      row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
      {
        std::size_t diagonal = row[0];
        row[0]               = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
          {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
          }
      }
    return row[b.size()];
  }

  /// @p name in lower case without blanks and punctuation.
  std::string
  folded(const std::string &name)
  {
    std::string result;
    for (const char c : name)
      if (std::isalnum(static_cast<unsigned char>(c)))
        result += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return result;
  }

  /// The subsections open at line @p line of @p file ("A/B"; "" at the
  /// top level), or nullopt if the scan of @p prm_file does not reach it.
  std::optional<std::string>
  section_at(const std::string &prm_file, const std::string &file, const std::string &line)
  {
    std::vector<std::string> path;
    if (!subsections_at(prm_file, file, std::stoul(line), path))
      return std::nullopt;
    std::string section;
    for (const std::string &part : path)
      section += (section.empty() ? "" : "/") + part;
    return section;
  }

  /// ParameterHandler's message for a value its pattern refuses names the
  /// key without its subsection: returned with it; "" for any other
  /// message.
  std::string
  value_mismatch_message(const std::string &message, const std::string &prm_file)
  {
    static const std::regex mismatch("^Line <([0-9]+)> of file <(.*)>: The entry value (.*) for "
                                     "the entry named (.*) does not match the given pattern: "
                                     "(.*)$");
    std::smatch match;
    if (!std::regex_match(message, match, mismatch))
      return "";
    const auto section = section_at(prm_file, match[2].str(), match[1].str());
    if (!section)
      return "";
    return "Line <" + match[1].str() + "> of file <" + match[2].str() + ">: " +
           (section->empty() ? "" : *section + "/") + match[4].str() + " = '" +
           contact_fem::excerpt(match[3].str()) + "' is not a valid value; expected " +
           match[5].str() + ".";
  }

  /// ParameterHandler's message for an unknown key ("Line <3> of file
  /// <x.prm>: No entry with name <K> was declared in the current
  /// subsection.") names no subsection. Returns it with the subsection the
  /// key was read in, where a key of that name is declared instead, or a
  /// key of that subsection spelt nearly so; "" for any other message.
  std::string
  unknown_key_message(const std::string &message,
                      const std::string &prm_file,
                      const ParameterHandler &prm)
  {
    static const std::regex unknown(
      "^Line <([0-9]+)> of file <(.*)>: No entry with name <(.*)> was declared in the current "
      "subsection\\.$");
    std::smatch match;
    if (!std::regex_match(message, match, unknown))
      return "";
    const std::string        file = match[2].str(), name = match[3].str();
    const auto               found_section = section_at(prm_file, file, match[1].str());
    if (!found_section)
      return "";
    const std::string section = *found_section;
    const std::string where =
      section.empty() ? "at the top level" : "in subsection '" + section + "'";
    const boost::property_tree::ptree  declared = declared_parameters(prm);
    const boost::property_tree::ptree &node     = subsection_node(declared, section);
    std::string advice;
    // The same name elsewhere: a key written in the wrong subsection.
    std::vector<std::pair<std::string, bool>> found;
    find_entry(declared, name, "", found);
    std::vector<std::string> keys, sections;
    for (const auto &[other, key] : found)
      if (key)
        keys.push_back(other.empty() ? "the top level" : "'" + other + "'");
      else
        sections.push_back(other.empty() ? "at the top level" : "in '" + other + "'");
    const auto listed = [](const std::vector<std::string> &names) {
      std::string text;
      for (unsigned int i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
      return text;
    };
    if (!keys.empty())
      advice += "; '" + name + "' is a key of " +
                (keys[0] == "the top level" ? "" : keys.size() == 1 ? "subsection " : "subsections ") +
                listed(keys);
    if (!sections.empty())
      advice += "; '" + name + "' is a subsection (entered by 'subsection " + name +
                "', not set) " + listed(sections);
    // A near spelling in the subsection itself: a typing error.
    std::vector<std::string> near;
    if (advice.empty())
      for (const auto &[key, child] : node)
        if (is_key(child))
          {
            const std::string a = folded(demangle(key)), b = folded(name);
            if (a == b || edit_distance(a, b) <= std::min<std::size_t>(2, b.size() / 4))
              near.push_back(demangle(key));
          }
    for (unsigned int i = 0; i < near.size(); ++i)
      advice += (i == 0 ? "; did you mean '" : "' or '") + near[i] +
                (i + 1 == near.size() ? "'?" : "");
    return "Line <" + match[1].str() + "> of file <" + file + ">: no key '" + name + "' " + where +
           advice + " (--print-parameters lists every subsection and key).";
  }

  /// ParameterHandler's message for a value its pattern accepts but the
  /// conversion does not ("Can't convert the parameter value <1e-320> for
  /// entry <End time> to a double precision variable.": an underflow or an
  /// overflow of strtod, after the file was read) names neither the file
  /// nor the subsection. (An integer's pattern refuses what an int does
  /// not hold.) Returns it with the keys of that name that hold that value
  /// and what a double holds; "" for any other message.
  std::string
  conversion_message(const std::string      &message,
                     const std::string      &prm_file,
                     const ParameterHandler &prm)
  {
    static const std::regex cannot("^Can't convert the parameter value <(.*)> for entry <(.*)> "
                                   "to a double precision variable\\.$");
    std::smatch match;
    if (!std::regex_match(message, match, cannot))
      return "";
    const std::string value = match[1].str(), name = match[2].str();
    std::vector<std::pair<std::string, bool>> found;
    const boost::property_tree::ptree         declared = declared_parameters(prm);
    find_entry(declared, name, "", found);
    // The values from the declared tree: the handler may still stand in
    // the subsection whose parsing threw.
    const auto value_of = [&](const std::string &section) {
      for (const auto &[key, child] : subsection_node(declared, section))
        if (demangle(key) == name && is_key(child))
          return child.get<std::string>("value");
      return std::string();
    };
    std::string keys;
    for (const auto &[section, key] : found)
      if (key && value_of(section) == value)
        keys += (keys.empty() ? "" : ", ") + (section.empty() ? "" : section + "/") + name;
    if (keys.empty())
      return "";
    return prm_file + ": " + keys + " = '" + contact_fem::excerpt(value) +
           "' is beyond the range of double precision (magnitudes from 2.2e-308 to 1.8e+308, "
           "or 0); expected a number in that range.";
  }

  /// Every parameter with its default, its allowed values and its
  /// documentation, in .prm syntax (so the listing is a valid input file).
  void
  print_parameter_tree(const boost::property_tree::ptree &tree,
                       const unsigned int                 indent,
                       std::ostream                      &out)
  {
    const std::string pad(indent, ' ');
    for (const auto &[key, child] : tree)
      if (child.count("value") && child.count("default_value"))
        {
          out << pad << "# " << child.get<std::string>("documentation") << "\n"
              << pad << "# Allowed: " << child.get<std::string>("pattern_description") << "\n"
              << pad << "set " << demangle(key) << " = " << child.get<std::string>("default_value")
              << "\n\n";
        }
    for (const auto &[key, child] : tree)
      if (!(child.count("value") && child.count("default_value")) && !child.empty())
        {
          out << pad << "subsection " << demangle(key) << "\n";
          print_parameter_tree(child, indent + 2, out);
          out << pad << "end\n\n";
        }
  }

  template <int dim>
  int
  run(ParameterHandler  &prm,
      const std::string &name,
      const std::string &directory,
      const bool         validate_only)
  {
    // The problem is destroyed before an error is reported, so that its
    // MPI-aware members shut down normally.
    std::exception_ptr error;
    int                code    = 0;
    bool               solving = false;
    {
      contact_fem::ContactProblem<dim> problem(prm, name, directory);
      try
        {
          if (validate_only)
            problem.validate();
          else
            code = problem.run();
        }
      catch (...)
        {
          error   = std::current_exception();
          solving = problem.started_solving();
        }
    }
    if (error && solving)
      try
        {
          std::rethrow_exception(error);
        }
      catch (const std::exception &e)
        {
          // After the first solve: a failure of the run, not bad input.
          if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            std::cerr << "contact_fem: error: " << contact_fem::user_message(e) << std::endl;
          return 2;
        }
    if (error)
      std::rethrow_exception(error);
    return code;
  }

  /**
   * A run started without mpirun (an Open MPI "singleton") would fork and
   * exec an orted daemon in MPI_Init: 0.2 s of wall and 0.06 s of process
   * time of the default scene (doc/performance.md, "Start-up"). It needs
   * none (it never spawns processes), so it runs as an isolated singleton,
   * with a session directory of its own: isolated singletons otherwise
   * share one (job family 0), which the first to finish removes under the
   * others. Constructed before MPI, destroyed after MPI_Finalize. A
   * launcher's variables, or the user's own settings, leave all as it is.
   */
  class SingletonSession
  {
  public:
    SingletonSession()
    {
      for (const char *set : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE",
                              "OMPI_MCA_ess_singleton_isolated", "OMPI_MCA_orte_tmpdir_base"})
        if (std::getenv(set))
          return;
      const char *tmp     = std::getenv("TMPDIR");
      std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/contact_fem.XXXXXX";
      if (mkdtemp(pattern.data()) == nullptr)
        return;
      directory = pattern;
      setenv("OMPI_MCA_orte_tmpdir_base", directory.c_str(), 1);
      setenv("OMPI_MCA_ess_singleton_isolated", "1", 1);
      // One process talks to no one: Open MPI's default choice of messaging
      // layer initialises the network libraries (libfabric, PSM, UCX) for
      // 0.2 s of wall time; ob1 over self and shared memory starts at once.
      if (!std::getenv("OMPI_MCA_pml"))
        setenv("OMPI_MCA_pml", "ob1", 1);
    }

    ~SingletonSession()
    {
      std::error_code error;
      if (!directory.empty())
        std::filesystem::remove_all(directory, error);
    }

  private:
    std::string directory;
  };
} // namespace

int
main(int argc, char **argv)
{
  const SingletonSession           session;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                       root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  contact_fem::install_interrupt_handlers();
  try
    {
      const CommandLine cl = parse_command_line(argc, argv);
      ParameterHandler  prm;
      contact_fem::ContactProblem<2>::declare_parameters(prm);
      if (cl.help)
        {
          if (root)
            std::cout << usage;
          return 0;
        }
      if (cl.print_parameters)
        {
          if (root)
            {
              std::cout << "# contact_fem parameters: default values, allowed values and "
                           "documentation.\n\n";
              print_parameter_tree(declared_parameters(prm), 0, std::cout);
            }
          return 0;
        }
      if (cl.prm_file.empty())
        throw std::runtime_error("no parameter file given.\n\n" + std::string(usage));
      check_parameter_file(cl.prm_file);
      try
        {
          prm.parse_input(cl.prm_file);
        }
      catch (const std::exception &e)
        {
          // ParameterHandler's messages for an unknown key or a refused
          // value name no subsection: the file is read again to name it.
          const std::string message = contact_fem::user_message(e);
          std::string       better  = unknown_key_message(message, cl.prm_file, prm);
          if (better.empty())
            better = value_mismatch_message(message, cl.prm_file);
          if (better.empty())
            throw;
          throw std::runtime_error(better);
        }
      // The declared tree (a JSON round trip) only checks --set options.
      const boost::property_tree::ptree declared =
        cl.overrides.empty() ? boost::property_tree::ptree() : declared_parameters(prm);
      for (const auto &[path, value] : cl.overrides)
        apply_override(prm, declared, path, value);
      if (!cl.output_directory.empty())
        prm.set("Output directory", cl.output_directory);

      // The scene name is the file name without directory and extension.
      std::string name        = cl.prm_file.substr(cl.prm_file.find_last_of('/') + 1);
      name                    = name.substr(0, name.find_last_of('.'));
      const auto        slash = cl.prm_file.find_last_of('/');
      const std::string directory =
        slash == std::string::npos ? std::string(".") : cl.prm_file.substr(0, slash);

      const int dim = prm.get_integer("Dimension");
      if (dim != 2 && dim != 3)
        throw std::runtime_error("Dimension = " + std::to_string(dim) +
                                 ": only 2D and 3D scenes exist.");
      try
        {
          return dim == 2 ? run<2>(prm, name, directory, cl.validate) :
                            run<3>(prm, name, directory, cl.validate);
        }
      catch (const std::exception &e)
        {
          // A value that passed its pattern but overflows its type.
          const std::string better =
            conversion_message(contact_fem::user_message(e), cl.prm_file, prm);
          if (better.empty())
            throw;
          throw std::runtime_error(better);
        }
    }
  catch (const contact_fem::Interrupted &e)
    {
      // Before the output directory was prepared: nothing to mark.
      if (root)
        std::cerr << "contact_fem: " << e.what() << " before the first load step." << std::endl;
      return 128 + e.signal;
    }
  catch (const std::bad_alloc &)
    {
      if (root)
        std::cerr << "contact_fem: error: out of memory (std::bad_alloc) while setting up the "
                     "scene: the mesh needs more memory than the run may use (RAM, cgroup "
                     "or ulimit -v); refine less."
                  << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      if (root)
        std::cerr << "contact_fem: error: " << contact_fem::user_message(e) << std::endl;
      return 1;
    }
}
