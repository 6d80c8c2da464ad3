// contact_fem::user_message() on deal.II's exceptions: a Trilinos error
// code (an entry summed into a matrix outside its sparsity pattern, seen as
// "error number 2") is named as an internal error to report, with its code;
// a plain message passes unchanged.

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/exceptions.h>

#include <contact_fem/core/parameters.h>

#include <iostream>
#include <stdexcept>

using namespace dealii;

int
main()
{
  deal_II_exceptions::disable_abort_on_exception();
  try
    {
      AssertThrow(false, LACExceptions::ExcTrilinosError(2));
    }
  catch (const std::exception &e)
    {
      std::cout << contact_fem::user_message(e) << std::endl;
    }
  const std::runtime_error plain("Contact/Pairs: boundary id 9 is on no face of the mesh");
  std::cout << contact_fem::user_message(plain) << std::endl;
}
