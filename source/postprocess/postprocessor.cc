#include <contact_fem/postprocess/postprocessor.h>

#include <map>
#include <utility>

namespace contact_fem
{
  namespace
  {
    /// The postprocessors by (rank, name), filled by the registrations at
    /// load time (a function's static: whatever the order of the files'
    /// initialisation); the key orders them.
    template <int dim>
    struct Entry
    {
      typename Postprocessor<dim>::Factory     create;
      typename Postprocessor<dim>::Declaration declare;
    };

    template <int dim>
    std::map<std::pair<int, std::string>, Entry<dim>> &
    postprocessors()
    {
      static std::map<std::pair<int, std::string>, Entry<dim>> registry;
      return registry;
    }
  } // namespace

  template <int dim>
  std::vector<double>
  RunView<dim>::probe_displacements() const
  {
    // Each DoF is added by its owner only, so the sum over ranks is its value.
    std::vector<double> values(probe_dofs.size() * dim, 0.);
    for (unsigned int i = 0; i < probe_dofs.size(); ++i)
      for (unsigned int d = 0; d < probe_dofs[i].size(); ++d)
        if (owned_solution.locally_owned_elements().is_element(probe_dofs[i][d]))
          values[i * dim + d] = owned_solution(probe_dofs[i][d]);
    Utilities::MPI::sum(values, comm, values);
    return values;
  }

  template <int dim>
  void
  Postprocessor<dim>::register_postprocessor(const std::string &name,
                                             const int          rank,
                                             const Factory     &factory,
                                             const Declaration  declare)
  {
    postprocessors<dim>()[{rank, name}] = {factory, declare};
  }

  template <int dim>
  void
  Postprocessor<dim>::declare_all_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    for (const auto &[key, entry] : postprocessors<dim>())
      entry.declare(prm);
    prm.leave_subsection();
  }

  template <int dim>
  std::vector<std::unique_ptr<Postprocessor<dim>>>
  Postprocessor<dim>::create_wanted(const PostprocessorContext<dim> &context)
  {
    std::vector<std::unique_ptr<Postprocessor<dim>>> wanted;
    for (const auto &[key, entry] : postprocessors<dim>())
      if (auto postprocessor = entry.create(context))
        wanted.push_back(std::move(postprocessor));
    return wanted;
  }

  template struct RunView<2>;
  template struct RunView<3>;
  template class Postprocessor<2>;
  template class Postprocessor<3>;
} // namespace contact_fem
