// WarningLog: a warning kind is printed in the first cycle that gives it
// (every warning of that kind in that cycle, e.g. one per body), never in a
// later cycle, and counted once per cycle; the repeats line names the
// cycles of the kinds given in more than one.

#include <contact_fem/core/warning_log.h>

#include <iostream>

int
main()
{
  using contact_fem::WarningLog;
  WarningLog log;
  std::cout << "empty at start: " << log.empty() << '\n';
  // Cycle 0: two bodies turn too easily, and the strain is large.
  std::cout << "cycle 0 rotation body 1 printed: " << log.add("rotation_warning", 0) << '\n';
  std::cout << "cycle 0 rotation body 2 printed: " << log.add("rotation_warning", 0) << '\n';
  std::cout << "cycle 0 strain printed: " << log.add("small_strain_warning", 0) << '\n';
  // Cycle 1: the same kinds again, and a new one.
  std::cout << "cycle 1 rotation printed: " << log.add("rotation_warning", 1) << '\n';
  std::cout << "cycle 1 balance printed: " << log.add("balance_warning", 1) << '\n';
  // Cycle 2: rotation again.
  std::cout << "cycle 2 rotation printed: " << log.add("rotation_warning", 2) << '\n';
  std::cout << "empty: " << log.empty() << '\n';
  std::cout << log.repeats();
  log.to_json().write(std::cout);
  std::cout << '\n';
}
