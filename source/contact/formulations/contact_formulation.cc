#include <contact_fem/contact/formulations/contact_formulation.h>
// The keys of the normal part, which every formulation shares.
#include <contact_fem/contact/formulations/frictionless_formulation.h>
#include <contact_fem/contact/friction/frictional_law.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <set>
#include <utility>

namespace contact_fem
{
  namespace
  {
    /// The registered formulations, frictionless ones first, each group
    /// in alphabetical order (the order of the names in the parameter
    /// documentation, whatever order the library's files are loaded in).
    template <int dim>
    std::vector<typename ContactFormulation<dim>::Registration> &
    registry()
    {
      static std::vector<typename ContactFormulation<dim>::Registration> entries;
      return entries;
    }
  } // namespace

  template <int dim>
  void
  ContactFormulation<dim>::register_formulation(const Registration &registration)
  {
    auto &entries = registry<dim>();
    entries.push_back(registration);
    std::stable_sort(entries.begin(), entries.end(), [](const auto &a, const auto &b) {
      return std::make_pair(a.takes_friction, a.name) < std::make_pair(b.takes_friction, b.name);
    });
  }

  template <int dim>
  void
  ContactFormulation<dim>::add_constraints(const ContactInterface<dim> &,
                                           const std::vector<double> &,
                                           AffineConstraints<double> &,
                                           const bool) const
  {}

  template <int dim>
  void
  ContactFormulation<dim>::recover_through_chains(
    const ContactInterface<dim>                            &interface,
    const std::vector<double>                              &residual,
    const std::function<void(const std::vector<double> &)> &recover) const
  {
    recover(residual);
    if (!interface.has_chained_nodes())
      return;
    for (unsigned int pass = 1; pass < interface.pairs.size(); ++pass)
      {
        // The residual of a node's own pair: the forces of the slaves it is
        // a master of added back (-M_kj lambda_k on master j, D_k lambda_k
        // on slave k, lambda_k = traction()).
        std::vector<double> own = residual;
        for (const auto &s : interface.slave_nodes)
          if (s.paired)
            {
              const Tensor<1, dim> lambda = traction(s);
              if (lambda.norm_square() == 0.)
                continue;
              for (const auto &[m, value] : s.M)
                if (interface.nodes[m].slave)
                  for (unsigned int d = 0; d < dim; ++d)
                    own[interface.position(interface.nodes[m].dofs[d])] += value * lambda[d];
            }
        recover(own);
      }
  }

  template <int dim>
  void
  ContactFormulation<dim>::add_sparsity(const ContactInterface<dim> &,
                                        const AffineConstraints<double> &,
                                        const IndexSet &,
                                        DynamicSparsityPattern &) const
  {}

  template <int dim>
  void
  ContactFormulation<dim>::add_closed_couplings(const std::vector<types::global_dof_index> &dofs,
                                                const AffineConstraints<double> &constraints,
                                                DynamicSparsityPattern          &pattern)
  {
    std::set<types::global_dof_index> closure(dofs.begin(), dofs.end());
    for (const auto dof : dofs)
      if (constraints.can_store_line(dof))
        if (const auto *entries = constraints.get_constraint_entries(dof))
          for (const auto &entry : *entries)
            closure.insert(entry.first);
    const std::vector<types::global_dof_index> all(closure.begin(), closure.end());
    for (const auto row : all)
      pattern.add_entries(row, all.begin(), all.end(), true);
  }

  template <int dim>
  void
  ContactFormulation<dim>::assemble(const ContactInterface<dim> &,
                                    const AffineConstraints<double> &,
                                    const AffineConstraints<double> &,
                                    const IndexSet &,
                                    TrilinosWrappers::SparseMatrix &,
                                    TrilinosWrappers::MPI::Vector &) const
  {}

  template <int dim>
  void
  ContactFormulation<dim>::print_results(const ContactInterface<dim> &,
                                         const std::vector<double> &,
                                         const Json &,
                                         const Json &,
                                         std::ostream &) const
  {}

  template <int dim>
  std::vector<double>
  ContactFormulation<dim>::pressures(const ContactInterface<dim> &interface) const
  {
    std::vector<double> result(interface.nodes.size());
    for (unsigned int n = 0; n < result.size(); ++n)
      result[n] = normal_pressure(n);
    return result;
  }

  template <int dim>
  std::vector<int>
  ContactFormulation<dim>::contact_sets() const
  {
    return {};
  }

  template <int dim>
  Tensor<1, dim>
  ContactFormulation<dim>::tangent(const Tensor<1, dim> &normal)
  {
    Tensor<1, dim> t;
    if constexpr (dim == 2)
      {
        // Turned counterclockwise, whatever the direction: an orientation
        // taken from the global axes would flip between neighbouring nodes
        // (and between load steps) on an interface along the y axis.
        t[0] = -normal[1];
        t[1] = normal[0];
      }
    else
      AssertThrow(false, ExcMessage("the contact tangent is only defined in 2D"));
    return t;
  }

  template <int dim>
  void
  ContactFormulation<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Formulation", "alm frictionless", Patterns::Selection(names()),
                      "Contact formulation: 'alm frictionless' = augmented "
                      "Lagrangian, dual mortar, scalar normal multiplier, "
                      "semi-smooth Newton: the gap of an active node is an exact "
                      "constraint. 'penalty frictionless' = the same mortar gap, "
                      "regularised: pressure = eps * penetration, so the bodies "
                      "overlap by pressure / eps (no multipliers, no constraints). "
                      "'alm frictional' = 'alm frictionless' plus the tangential "
                      "traction of the law of Contact/Friction (Coulomb or Tresca), "
                      "stick/slip semi-smooth Newton (the slip direction linearised "
                      "in 3D), 2D and 3D, small sliding. "
                      "'penalty frictional' = 'penalty frictionless' plus a "
                      "tangential penalty (Contact/Tangential penalty) on the slip "
                      "increment of the load step, return mapping to the slip bound "
                      "of the law of Contact/Friction: a sticking node slips "
                      "elastically by t / eps_t; unsymmetric system under Coulomb "
                      "slip; 2D and 3D, small sliding. "
                      "'mpc frictionless' = multipoint constraints: the normal "
                      "displacement of an active slave node is eliminated through "
                      "the dual mortar relation n.u_s = n.(D^-1 M u_m) + g (the "
                      "constraint of 'alm frictionless'); the active set needs no "
                      "penalty (Contact/Penalty must stay auto): a node is released "
                      "when its recovered reaction pulls, an inactive node that "
                      "penetrates becomes active. Same converged answer as 'alm "
                      "frictionless'. 'mpc frictional' = 'mpc frictionless' plus "
                      "the law of Contact/Friction: on a stick node every component "
                      "is eliminated (u_s = D^-1 M u_m + offsets), on a slip node "
                      "the normal one, its tangential traction T(p) (Coulomb mu p) "
                      "opposing the slip (not slip treated as frictionless); a "
                      "stick node slips when its recovered tangential traction "
                      "reaches T(p), a slip node sticks when its slip turns back; "
                      "2D and 3D, small sliding; the answers of 'alm frictional'.");
    prm.leave_subsection();
    FrictionlessFormulation<dim>::Parameters::declare_parameters(prm);
    FrictionParameters::declare_parameters(prm);
    for (const auto &entry : registry<dim>())
      if (entry.declare)
        entry.declare(prm);
  }

  template <int dim>
  std::unique_ptr<ContactFormulation<dim>>
  ContactFormulation<dim>::create(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    const std::string name = prm.get("Formulation");
    prm.leave_subsection();
    for (const auto &entry : registry<dim>())
      if (entry.name == name)
        {
          // The shared friction keys are read here, once, for the
          // formulations that take them.
          FrictionParameters friction;
          if (entry.takes_friction)
            friction.parse_parameters(prm);
          auto formulation = entry.create(prm, friction);
          // A key the formulation would ignore is a mistake worth a message.
          prm.enter_subsection("Contact");
          const bool friction_given = !Utilities::trim(prm.get("Friction")).empty();
          const bool pure_slip      = prm.get_bool("Pure slip");
          const bool tangential_penalty_given =
            Utilities::trim(prm.get("Tangential penalty")) != "auto";
          prm.leave_subsection();
          AssertThrow(entry.takes_friction || !pure_slip,
                      ExcMessage("Contact/Pure slip = true, but Contact/Formulation = " + name +
                                 " has no friction: the key concerns the frictional "
                                 "formulations only."));
          AssertThrow(entry.takes_tangential_penalty || !tangential_penalty_given,
                      ExcMessage("Contact/Tangential penalty is set, but only Contact/"
                                 "Formulation = penalty frictional has a tangential penalty (" +
                                 name + " would ignore it)."));
          AssertThrow(entry.takes_friction || !friction_given,
                      ExcMessage("Contact/Friction is set, but Contact/Formulation = " + name +
                                 " has no friction: use a frictional formulation (" +
                                 frictional_names() + "), or leave Contact/Friction empty."));
          return formulation;
        }
    AssertThrow(false, ExcMessage("Contact/Formulation: unknown formulation '" + name + "'."));
    return nullptr;
  }

  template <int dim>
  std::string
  ContactFormulation<dim>::names()
  {
    std::string result;
    for (const auto &entry : registry<dim>())
      result += (result.empty() ? "" : "|") + entry.name;
    return result;
  }

  template <int dim>
  std::string
  ContactFormulation<dim>::frictional_names()
  {
    std::string result;
    for (const auto &entry : registry<dim>())
      if (entry.takes_friction)
        result += (result.empty() ? "" : ", ") + entry.name;
    return result;
  }

  template class ContactFormulation<2>;
  template class ContactFormulation<3>;
} // namespace contact_fem
