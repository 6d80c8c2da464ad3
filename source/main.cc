// contact_fem: runs one scene described by a ParameterHandler file.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <contact_fem/simulator/contact_problem.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cctype>
#include <filesystem>
#include <fstream>
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
    "  --validate                 read and check the file, then exit\n"
    "\n"
    "Exit codes: 0 success, 1 bad input, 2 the solver failed (the results of\n"
    "the last converged load step are written and marked as such).\n";

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
        const std::string arg = argv[i];
        auto next = [&](const std::string &option) {
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
            if (eq == std::string::npos || eq == 0)
              throw std::runtime_error("--set '" + assignment +
                                       "': expected \"Subsection/Key=value\".");
            cl.overrides.emplace_back(assignment.substr(0, eq), assignment.substr(eq + 1));
          }
        else if (arg == "--output-directory")
          cl.output_directory = next(arg);
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

  /// Refuses a parameter file that is a directory or holds no settings:
  /// ParameterHandler reads both as an empty file and the run would solve
  /// the default scene as if asked to.
  void
  check_parameter_file(const std::string &file)
  {
    std::error_code error;
    if (std::filesystem::is_directory(file, error))
      throw std::runtime_error("the parameter file '" + file +
                               "' is a directory; expected a .prm file.");
    std::ifstream in(file);
    if (!in)
      throw std::runtime_error("cannot open the parameter file '" + file + "'.");
    const bool prm_syntax = file.size() < 5 || (file.substr(file.size() - 5) != ".json" &&
                                                file.substr(file.size() - 4) != ".xml");
    std::string line;
    bool        empty = true, settings = false;
    while (std::getline(in, line))
      {
        empty    = empty && line.find_first_not_of(" \t\r") == std::string::npos;
        settings = settings || (prm_syntax ? is_setting(line) : !empty);
      }
    if (empty)
      throw std::runtime_error("the parameter file '" + file +
                               "' is empty: it has no settings (an empty file would run "
                               "the default scene).");
    if (!settings)
      throw std::runtime_error("the parameter file '" + file +
                               "' has no settings, only comments or subsections (it would "
                               "run the default scene).");
  }

  /// Applies "A/B/Key=value" by parsing the equivalent prm text, so that the
  /// same checks and messages as for the file apply.
  void
  apply_override(ParameterHandler &prm, const std::string &path, const std::string &value)
  {
    std::vector<std::string> parts = Utilities::split_string_list(path, '/');
    std::string              text;
    for (unsigned int i = 0; i + 1 < parts.size(); ++i)
      text += "subsection " + parts[i] + "\n";
    text += "set " + parts.back() + " = " + value + "\n";
    for (unsigned int i = 0; i + 1 < parts.size(); ++i)
      text += "end\n";
    try
      {
        prm.parse_input_from_string(text, "--set " + path + "=" + value);
      }
    catch (const std::exception &e)
      {
        throw std::runtime_error("--set \"" + path + "=" + value + "\": " + e.what());
      }
  }

  /// The message of an exception without deal.II's source location and
  /// stack trace: users need the "Additional information" only.
  std::string
  clean_message(const std::exception &e)
  {
    std::string       text = e.what();
    const std::string key  = "Additional information:";
    const auto        pos  = text.find(key);
    if (pos != std::string::npos)
      {
        text = text.substr(pos + key.size());
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
    return result;
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
              << pad << "# Allowed: " << child.get<std::string>("pattern_description")
              << "\n"
              << pad << "set " << demangle(key) << " = "
              << child.get<std::string>("default_value") << "\n\n";
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
  run(ParameterHandler &prm, const std::string &name, const std::string &directory,
      const bool validate_only)
  {
    // The problem is destroyed before an error is reported, so that its
    // MPI-aware members shut down normally.
    std::string error;
    int         code = 0;
    {
      contact_fem::ContactProblem<dim> problem(prm, name, directory);
      if (validate_only)
        {
          problem.print_input_warnings();
          return 0;
        }
      try
        {
          code = problem.run();
        }
      catch (const std::exception &e)
        {
          error = clean_message(e);
        }
    }
    if (!error.empty())
      throw std::runtime_error(error);
    return code;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
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
              std::stringstream json;
              prm.print_parameters(json, ParameterHandler::JSON);
              boost::property_tree::ptree tree;
              boost::property_tree::read_json(json, tree);
              std::cout << "# contact_fem parameters: default values, allowed values and "
                           "documentation.\n\n";
              print_parameter_tree(tree, 0, std::cout);
            }
          return 0;
        }
      if (cl.prm_file.empty())
        throw std::runtime_error("no parameter file given.\n\n" + std::string(usage));
      check_parameter_file(cl.prm_file);
      prm.parse_input(cl.prm_file);
      for (const auto &[path, value] : cl.overrides)
        apply_override(prm, path, value);
      if (!cl.output_directory.empty())
        prm.set("Output directory", cl.output_directory);

      // The scene name is the file name without directory and extension.
      std::string       name = cl.prm_file.substr(cl.prm_file.find_last_of('/') + 1);
      name                   = name.substr(0, name.find_last_of('.'));
      const auto        slash = cl.prm_file.find_last_of('/');
      const std::string directory =
        slash == std::string::npos ? std::string(".") : cl.prm_file.substr(0, slash);

      const int dim = prm.get_integer("Dimension");
      if (dim != 2 && dim != 3)
        throw std::runtime_error("Dimension = " + std::to_string(dim) +
                                 ": only 2D and 3D scenes exist.");
      return dim == 2 ? run<2>(prm, name, directory, cl.validate) :
                        run<3>(prm, name, directory, cl.validate);
    }
  catch (const std::exception &e)
    {
      if (root)
        std::cerr << "contact_fem: error: " << clean_message(e) << std::endl;
      return 1;
    }
}
