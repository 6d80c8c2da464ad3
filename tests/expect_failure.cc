// Test driver for bad input: runs contact_fem on the .prm file given as the
// argument, prints what it said (with the test directory replaced by <dir>,
// so the output does not depend on where the sources are) and its exit
// status. Succeeds only if contact_fem failed with a non-zero exit code and
// did not crash (no signal, no abort).
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

int
main(int argc, char **argv)
{
  if (argc != 2)
    {
      std::cerr << "usage: expect_failure FILE.prm" << std::endl;
      return 2;
    }
  const std::string prm       = argv[1];
  const std::string directory = prm.substr(0, prm.find_last_of('/'));
  // Options for the run may follow a "# args:" line in the .prm file
  // (e.g. --validate, to check that it catches the error too).
  std::string   options;
  std::ifstream in(prm);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("# args:", 0) == 0)
      options += " " + line.substr(7);
  std::string command = std::string(CONTACT_FEM_EXECUTABLE) + options + " '" + prm +
                        "' --output-directory results 2>&1";
  FILE *pipe = popen(command.c_str(), "r");
  if (!pipe)
    return 2;
  std::string           text;
  std::array<char, 4096> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe))
    text += buffer.data();
  const int status = pclose(pipe);

  for (std::size_t pos = text.find(directory); pos != std::string::npos;
       pos             = text.find(directory))
    text.replace(pos, directory.size(), "<dir>");
  std::cout << text;

  const bool exited = WIFEXITED(status);
  const int  code   = exited ? WEXITSTATUS(status) : -1;
  std::cout << "exit status: " << (exited ? (code != 0 ? "non-zero" : "zero") : "crashed")
            << std::endl;
  return (exited && code != 0) ? 0 : 1;
}
