// Superconvergent patch recovery (SPR) of the stress and the ZZ-type error
// estimator, with optional contact-traction penalty terms. See the class
// documentation in include/contact_fem/stress_recovery.h for the outline.
//
// Parallel layout (the result does not depend on the partition):
//  1. Every rank samples sigma_h on its locally owned and ghost cells.
//  2. Stage 1: the fit of a vertex patch is computed by the owner of that
//     vertex's degree of freedom in an auxiliary FE_Q(1) DoFHandler (the owner
//     has the vertex on a locally owned cell, so the whole patch is owned or
//     ghost there). The fit coefficients are stored in that DoFHandler's
//     vector, whose ghost import gives every rank the fits of all vertices of
//     its owned and ghost cells.
//  3. Stage 2: the owner of each unconstrained degree of freedom of the
//     recovered FE_Q(p) field computes its value from those fits; hanging
//     support points come from the hanging-node constraints (distribute()).
//  4. The indicators are integrated on the locally owned cells and summed.

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <deal.II/numerics/rtree.h>

#include <contact_fem/adaptivity/stress_recovery.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <tuple>
#include <utility>

namespace contact_fem
{
  void
  StressRecoverySettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Refinement");
    prm.declare_entry("SPR normal penalty", "1e4", Patterns::Double(0.),
                      "Weight of the normal-traction condition at a contact "
                      "node against the change of its SPR-fitted value: the "
                      "recovered normal traction moves penalty / (1 + penalty) "
                      "of the way to the contact pressure.");
    prm.declare_entry("SPR tangential penalty", "1e4", Patterns::Double(0.),
                      "Weight of the tangential-traction condition, on the "
                      "same scale (tangential relative to the node's normal, "
                      "moved penalty / (2 + penalty) of the way; frictionless "
                      "contact forces act "
                      "along the deformed normal, so on the reference "
                      "configuration this traction is small but not zero).");
    prm.leave_subsection();
  }

  void
  StressRecoverySettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Refinement");
    penalty_normal     = prm.get_double("SPR normal penalty");
    penalty_tangential = prm.get_double("SPR tangential penalty");
    prm.leave_subsection();
  }

  namespace
  {
    /// A patch fit is accepted with the full degree p only if the smallest
    /// singular value of its (scaled) normal matrix A = S^T S exceeds this
    /// fraction of the largest one (i.e. cond(S) < ~1e5).
    constexpr double rank_tolerance = 1e-10;

    /// ... and only if its Lebesgue constant on the patch (see fit_patch())
    /// is at most this. Measured: 2.5 (Q1) to 4.4 (Q2) on the 2D test scenes,
    /// 3.0-3.6 (Q1) and 4.4-6.5 (Q2, curved cells) on 3D patches that sample
    /// the volume around the vertex; 9 (exact interpolation of 4 samples,
    /// three cells of one level and a child of a refined one on a boundary
    /// face) up to 8e3 (centres near a plane) on the 3D Q1 patches at the
    /// coarse-fine boundaries of a locally refined mesh.
    constexpr double stability_limit = 8.;

    /// A contact node is located at a point if it lies within this fraction of
    /// the cell diameter of it.
    constexpr double location_tolerance = 1e-10;

    /// A contact node's normal must point out of a boundary face (n . n_face >
    /// this) for the node to constrain the patches containing that face: only
    /// the slave side gets the contact terms.
    constexpr double orientation_tolerance = 1e-8;

    /// Flags stored with a vertex fit.
    enum FitKind : unsigned int
    {
      no_fit      = 0, ///< nothing computed for this vertex and body
      full_fit    = 1, ///< complete polynomial of degree p
      reduced_fit = 2  ///< rank-deficient patch, fitted with a lower degree
    };

    /// Complete monomial basis of degree p in dim variables, ordered by total
    /// degree, so that the basis of degree d < p is a prefix.
    template <int dim>
    class MonomialBasis
    {
    public:
      explicit MonomialBasis(const unsigned int degree)
      {
        std::array<unsigned int, dim> e{};
        for (unsigned int d = 0; d <= degree; ++d)
          {
            append(d, 0, e);
            n_up_to_degree.push_back(exponents.size());
          }
      }

      unsigned int
      size() const
      {
        return exponents.size();
      }

      /// Number of monomials of total degree <= d.
      unsigned int
      size(const unsigned int d) const
      {
        return n_up_to_degree[d];
      }

      /// Values of the first n monomials at xi.
      void
      values(const Point<dim> &xi, const unsigned int n, std::vector<double> &phi) const
      {
        phi.resize(n);
        for (unsigned int k = 0; k < n; ++k)
          {
            double v = 1.;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int r = 0; r < exponents[k][i]; ++r)
                v *= xi[i];
            phi[k] = v;
          }
      }

    private:
      void
      append(const unsigned int remaining, const unsigned int pos, std::array<unsigned int, dim> &e)
      {
        if (pos == dim - 1)
          {
            e[pos] = remaining;
            exponents.push_back(e);
            return;
          }
        for (unsigned int a = remaining + 1; a-- > 0;)
          {
            e[pos] = a;
            append(remaining - a, pos + 1, e);
          }
      }

      std::vector<std::array<unsigned int, dim>> exponents;
      std::vector<unsigned int>                  n_up_to_degree;
    };

    /// The recovered polynomial of one vertex patch: for every independent
    /// stress component c (unrolled SymmetricTensor order) the coefficients
    /// coefficients[c * basis.size() + k] of the monomials in the coordinates
    /// xi = (x - centre) / h.
    template <int dim>
    struct PatchFit
    {
      unsigned int        kind = no_fit;
      Point<dim>          centre;
      double              h = 1.;
      std::vector<double> coefficients;
    };

    /// Number of independent components of a symmetric stress tensor.
    template <int dim>
    constexpr unsigned int n_stress = SymmetricTensor<2, dim>::n_independent_components;

    template <int dim>
    SymmetricTensor<2, dim>
    evaluate(const PatchFit<dim> &fit, const MonomialBasis<dim> &basis, const Point<dim> &x)
    {
      std::vector<double> phi;
      basis.values(Point<dim>((x - fit.centre) / fit.h), basis.size(), phi);
      SymmetricTensor<2, dim> sigma;
      for (unsigned int c = 0; c < n_stress<dim>; ++c)
        {
          double v = 0;
          for (unsigned int k = 0; k < basis.size(); ++k)
            v += fit.coefficients[c * basis.size() + k] * phi[k];
          sigma[SymmetricTensor<2, dim>::unrolled_to_component_indices(c)] = v;
        }
      return sigma;
    }

    /// Orthonormal tangents of the unit vector n (dim - 1 of them).
    template <int dim>
    std::vector<Tensor<1, dim>>
    tangents(const Tensor<1, dim> &n)
    {
      std::vector<Tensor<1, dim>> t;
      if constexpr (dim == 2)
        {
          Tensor<1, dim> t0;
          t0[0] = -n[1];
          t0[1] = n[0];
          t.push_back(t0);
        }
      else if constexpr (dim == 3)
        {
          // Cross n with the coordinate axis least aligned with it.
          unsigned int a = 0;
          for (unsigned int i = 1; i < 3; ++i)
            if (std::abs(n[i]) < std::abs(n[a]))
              a = i;
          Tensor<1, dim> e;
          e[a]              = 1.;
          Tensor<1, dim> t0 = cross_product_3d(n, e);
          t0 /= t0.norm();
          t.push_back(t0);
          t.push_back(cross_product_3d(n, t0));
        }
      else
        AssertThrow(false, ExcNotImplemented());
      return t;
    }

    template <int dim>
    class SPREstimator
    {
    public:
      using Result    = typename StressRecovery<dim>::Result;
      using Settings  = typename StressRecovery<dim>::Settings;
      using CellIt    = typename Triangulation<dim>::active_cell_iterator;
      using DoFCellIt = typename DoFHandler<dim>::active_cell_iterator;

      SPREstimator(const Mapping<dim>                          &mapping,
                   const DoFHandler<dim>                       &dof_handler,
                   const TrilinosWrappers::MPI::Vector         &solution,
                   const Materials<dim>                        &materials,
                   const std::vector<ContactNodeTraction<dim>> &contact_nodes,
                   const Settings                              &settings,
                   VolumetricProjection<dim>                   *volumetric);

      Result
      run();

    private:
      void
      collect_topology();
      /// FE strains and stresses at the points of @p fe_values (reinit on
      /// @p cell), with the projected volumetric strain under B-bar.
      void
      fe_stresses(const DoFCellIt                      &cell,
                  const FEValues<dim>                  &fe_values,
                  std::vector<SymmetricTensor<2, dim>> &strains,
                  std::vector<SymmetricTensor<2, dim>> &stresses) const;
      void
      sample_stresses();
      /// Whether support point @p k of @p cell carries the displacement DoF
      /// of @p node (true if the node names none).
      bool
      has_node_dof(const CellIt &cell, const unsigned int k, const ContactNodeTraction<dim> &node) const;
      void
      match_contact_nodes();
      PatchFit<dim>
      fit_patch(const unsigned int vertex, const types::material_id body) const;
      bool
      has_body(const unsigned int vertex, const types::material_id body) const;
      unsigned int
      slot_of(const types::material_id body) const;
      void
      compute_vertex_fits();
      PatchFit<dim>
      read_fit(const unsigned int vertex, const types::material_id body) const;
      const std::vector<PatchFit<dim>> &
      effective_fit(const unsigned int vertex, const types::material_id body);
      template <typename Function>
      SymmetricTensor<2, dim>
      traction_correction(const std::size_t j, const Function &fitted) const;
      /// The vectors m_q with which the recovered stress gives the traction
      /// at the samples of contact node @p j (at its location without
      /// samples): the unit normal, or for a finite-strain body Nanson's
      /// J F^-T N (sigma* m_q is the nominal traction, per reference area).
      std::vector<Tensor<1, dim>>
      traction_vectors(const std::size_t j) const;
      void
      recover_nodal_values();
      Result
      integrate() const;

      const Mapping<dim>                          &mapping;
      const DoFHandler<dim>                       &dof_handler;
      const TrilinosWrappers::MPI::Vector         &solution;
      const Materials<dim>                        &materials;
      const std::vector<ContactNodeTraction<dim>> &contact_nodes;
      const Settings                               settings;
      VolumetricProjection<dim>                   *volumetric;

      const Triangulation<dim> &tria;
      const MPI_Comm            comm;
      const unsigned int        degree;
      const MonomialBasis<dim>  basis;

      /// Material ids of Materials::bodies in order; slot of a body.
      std::vector<types::material_id> bodies;
      /// 1 if no vertex is shared by two bodies (anywhere), else bodies.size():
      /// number of independent copies of every nodal field.
      unsigned int n_slots = 1;

      /// Non-artificial active cells around every vertex, and the (mapped)
      /// vertex position.
      std::vector<std::vector<CellIt>> vertex_cells;
      std::vector<Point<dim>>          vertex_point;

      /// Per active cell index: sampling points and FE stresses there.
      std::vector<std::vector<Point<dim>>>              sample_points;
      std::vector<std::vector<SymmetricTensor<2, dim>>> sample_stress;
      /// Per active cell index: (support point of fe_q, contact node) for the
      /// contact nodes at support points of its slave boundary faces.
      std::vector<std::vector<std::pair<unsigned int, std::size_t>>> cell_contacts;
      /// Per contact node: the cells found in cell_contacts for it.
      std::vector<std::vector<CellIt>> node_cells;

      /// Stage 1: per-vertex fits in an FE_Q(1) system (layout per slot:
      /// coefficients, h, kind).
      std::unique_ptr<FESystem<dim>>                  fe_fits;
      DoFHandler<dim>                                 dof_fits;
      TrilinosWrappers::MPI::Vector                   fits;
      std::vector<std::pair<DoFCellIt, unsigned int>> vertex_ref;
      unsigned int                                    fit_stride = 0;
      std::map<std::pair<unsigned int, types::material_id>, std::vector<PatchFit<dim>>>
        effective_cache;

      /// Stage 2: the recovered stress, FE_Q(p)^(n_slots * n_stress).
      FE_Q<dim>                      fe_q;
      std::unique_ptr<FESystem<dim>> fe_recovered;
      DoFHandler<dim>                dof_recovered;
      TrilinosWrappers::MPI::Vector  recovered;
      /// See Result::node_stresses.
      std::vector<SymmetricTensor<2, dim>> node_stresses;
    };

    template <int dim>
    SPREstimator<dim>::SPREstimator(const Mapping<dim>                          &mapping,
                                    const DoFHandler<dim>                       &dof_handler,
                                    const TrilinosWrappers::MPI::Vector         &solution,
                                    const Materials<dim>                        &materials,
                                    const std::vector<ContactNodeTraction<dim>> &contact_nodes,
                                    const Settings                              &settings,
                                    VolumetricProjection<dim>                   *volumetric)
      : mapping(mapping)
      , dof_handler(dof_handler)
      , solution(solution)
      , materials(materials)
      , contact_nodes(contact_nodes)
      , settings(settings)
      , volumetric(volumetric)
      , tria(dof_handler.get_triangulation())
      , comm(dof_handler.get_triangulation().get_communicator())
      , degree(dof_handler.get_fe().degree)
      , basis(dof_handler.get_fe().degree)
      , fe_q(dof_handler.get_fe().degree)
    {
      const FiniteElement<dim> &fe = dof_handler.get_fe();
      AssertThrow(fe.n_components() == dim && fe.n_base_elements() == 1 &&
                    fe.element_multiplicity(0) == dim &&
                    dynamic_cast<const FE_Q<dim> *>(&fe.base_element(0)) != nullptr,
                  ExcMessage("StressRecovery: the displacement element must be "
                             "FESystem(FE_Q<dim>(p), dim)."));
      AssertThrow(degree >= 1, ExcMessage("StressRecovery: degree must be >= 1."));
      AssertThrow(settings.penalty_normal >= 0. && settings.penalty_tangential >= 0.,
                  ExcMessage("StressRecovery: the contact penalties must be >= 0."));
      for (const auto &b : materials.bodies)
        bodies.push_back(b.first);
    }

    template <int dim>
    unsigned int
    SPREstimator<dim>::slot_of(const types::material_id body) const
    {
      if (n_slots == 1)
        return 0;
      const auto it = std::lower_bound(bodies.begin(), bodies.end(), body);
      Assert(it != bodies.end() && *it == body, ExcInternalError());
      return it - bodies.begin();
    }

    template <int dim>
    bool
    SPREstimator<dim>::has_body(const unsigned int vertex, const types::material_id body) const
    {
      for (const auto &cell : vertex_cells[vertex])
        if (cell->material_id() == body)
          return true;
      return false;
    }

    template <int dim>
    void
    SPREstimator<dim>::collect_topology()
    {
      vertex_cells.assign(tria.n_vertices(), {});
      vertex_point.assign(tria.n_vertices(), Point<dim>());
      for (const auto &cell : tria.active_cell_iterators())
        if (!cell->is_artificial())
          {
            AssertThrow(cell->reference_cell() == ReferenceCells::get_hypercube<dim>(),
                        ExcMessage("StressRecovery: only quadrilateral / hexahedral "
                                   "meshes are supported."));
            AssertThrow(materials.bodies.count(cell->material_id()) == 1,
                        ExcMessage("StressRecovery: the mesh has cells with material id " +
                                   std::to_string(cell->material_id()) +
                                   ", which the Materials do not list."));
            const auto points = mapping.get_vertices(cell);
            for (const unsigned int v : cell->vertex_indices())
              {
                vertex_cells[cell->vertex_index(v)].push_back(cell);
                vertex_point[cell->vertex_index(v)] = points[v];
              }
          }

      // Does any vertex carry cells of two bodies? Then every nodal field gets
      // one copy per body, so that the bodies stay separate there.
      unsigned int shared = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            for (const auto &other : vertex_cells[cell->vertex_index(v)])
              if (other->material_id() != cell->material_id())
                shared = 1;
      shared  = Utilities::MPI::max(shared, comm);
      n_slots = (shared != 0 ? bodies.size() : 1);
    }

    template <int dim>
    void
    SPREstimator<dim>::fe_stresses(const DoFCellIt                      &cell,
                                   const FEValues<dim>                  &fe_values,
                                   std::vector<SymmetricTensor<2, dim>> &strains,
                                   std::vector<SymmetricTensor<2, dim>> &stresses) const
    {
      const FEValuesExtractors::Vector displacement(0);
      fe_values[displacement].get_function_symmetric_gradients(solution, strains);
      stresses.resize(strains.size());
      if (materials.constants(cell->material_id()).model != ElasticModel::linear)
        {
          // A finite-strain body: the law's Cauchy stress at F = I + grad u
          // (of F, also under F-bar), at the reference points. The "strain"
          // is C^-1 : sigma of the body's linear law, so that the energy norm
          // below is the complementary energy of the law's small-strain limit
          // (the same metric as the estimate).
          std::vector<Tensor<2, dim>> gradients(strains.size());
          fe_values[displacement].get_function_gradients(solution, gradients);
          for (unsigned int q = 0; q < strains.size(); ++q)
            {
              const SymmetricTensor<2, 3> sigma =
                materials.finite_strain_stress(cell->material_id(), gradients[q]);
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = i; j < dim; ++j)
                  stresses[q][i][j] = sigma[i][j];
              strains[q] = materials.compliance(cell->material_id(), stresses[q]);
            }
          return;
        }
      if (volumetric == nullptr)
        {
          for (unsigned int q = 0; q < strains.size(); ++q)
            stresses[q] = materials.stress(cell->material_id(), strains[q]);
          return;
        }
      Vector<double> local_values(dof_handler.get_fe().n_dofs_per_cell());
      cell->get_dof_values(solution, local_values);
      volumetric->reinit(cell);
      for (unsigned int q = 0; q < strains.size(); ++q)
        stresses[q] =
          materials.stress(cell->material_id(), strains[q],
                           volumetric->value(local_values, fe_values.get_quadrature().point(q)));
    }

    template <int dim>
    void
    SPREstimator<dim>::sample_stresses()
    {
      // Sampling points: for Q1 the cell centre, the superconvergent point.
      // For Q2 the (p + 1)-point rule rather than the p-point one, whose
      // superconvergence needs uniform straight-sided cells: on the graded,
      // curved, hanging-node meshes of the adaptive loop the 3 x 3 points
      // give better-determined patch fits (also on boundary patches) and
      // measured effectivities of 1.1-1.2 instead of 1.4-1.8 on the Hertz
      // scene (doc/convergence.md).
      const QGauss<dim>                    quadrature(degree == 1 ? 1 : degree + 1);
      FEValues<dim>                        fe_values(mapping, dof_handler.get_fe(), quadrature,
                                                     update_gradients | update_quadrature_points);
      std::vector<SymmetricTensor<2, dim>> strains(quadrature.size());

      sample_points.assign(tria.n_active_cells(), {});
      sample_stress.assign(tria.n_active_cells(), {});
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            fe_values.reinit(cell);
            const unsigned int index = cell->active_cell_index();
            sample_points[index]     = fe_values.get_quadrature_points();
            fe_stresses(cell, fe_values, strains, sample_stress[index]);
          }
    }

    template <int dim>
    bool
    SPREstimator<dim>::has_node_dof(const CellIt                   &cell,
                                    const unsigned int              k,
                                    const ContactNodeTraction<dim> &node) const
    {
      if (node.dof == numbers::invalid_dof_index)
        return true;
      std::vector<types::global_dof_index> dofs(dof_handler.get_fe().n_dofs_per_cell());
      DoFCellIt(&tria, cell->level(), cell->index(), &dof_handler)->get_dof_indices(dofs);
      return dofs[dof_handler.get_fe().component_to_system_index(0, k)] == node.dof;
    }

    template <int dim>
    void
    SPREstimator<dim>::match_contact_nodes()
    {
      cell_contacts.assign(tria.n_active_cells(), {});
      node_cells.assign(contact_nodes.size(), {});
      if (contact_nodes.empty())
        return;

      std::vector<Point<dim>> locations;
      locations.reserve(contact_nodes.size());
      for (const auto &node : contact_nodes)
        {
          AssertThrow(node.normal.norm() > 0.,
                      ExcMessage("StressRecovery: a contact node has a zero normal."));
          locations.push_back(node.location);
        }
      const auto tree = pack_rtree_of_indices(locations);

      const std::vector<Point<dim>> &unit_points = fe_q.get_unit_support_points();
      const FE_Q<dim>                fe_geometry(1);
      FEFaceValues<dim> fe_face(mapping, fe_geometry, QGauss<dim - 1>(1), update_normal_vectors);
      std::vector<std::size_t> hits;

      for (const auto &cell : tria.active_cell_iterators())
        if (!cell->is_artificial())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const double   tolerance   = location_tolerance * cell->diameter();
                bool           have_normal = false;
                Tensor<1, dim> face_normal;
                // The support points of the recovered field on this face.
                for (unsigned int k = 0; k < unit_points.size(); ++k)
                  {
                    if (!fe_q.has_support_on_face(k, f))
                      continue;
                    const Point<dim> x = mapping.transform_unit_to_real_cell(cell, unit_points[k]);
                    Point<dim>       lower = x, upper = x;
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        lower[d] -= tolerance;
                        upper[d] += tolerance;
                      }
                    hits.clear();
                    tree.query(boost::geometry::index::intersects(
                                 BoundingBox<dim>(std::make_pair(lower, upper))),
                               std::back_inserter(hits));
                    for (const std::size_t j : hits)
                      {
                        if (locations[j].distance(x) > tolerance)
                          continue;
                        if (!have_normal)
                          {
                            fe_face.reinit(cell, f);
                            face_normal = fe_face.normal_vector(0);
                            have_normal = true;
                          }
                        const Tensor<1, dim> n =
                          contact_nodes[j].normal / contact_nodes[j].normal.norm();
                        if (n * face_normal > orientation_tolerance &&
                            has_node_dof(cell, k, contact_nodes[j]))
                          {
                            cell_contacts[cell->active_cell_index()].emplace_back(k, j);
                            node_cells[j].push_back(cell);

                          }
                      }
                  }
              }
    }

    template <int dim>
    PatchFit<dim>
    SPREstimator<dim>::fit_patch(const unsigned int vertex, const types::material_id body) const
    {
      PatchFit<dim> fit;
      fit.centre = vertex_point[vertex];

      std::vector<CellIt> cells;
      for (const auto &cell : vertex_cells[vertex])
        if (cell->material_id() == body)
          cells.push_back(cell);
      Assert(!cells.empty(), ExcInternalError());

      // Local coordinates: centred at the vertex, scaled by the patch radius.
      fit.h = 0;
      for (const auto &cell : cells)
        for (const Point<dim> &x : mapping.get_vertices(cell))
          fit.h = std::max(fit.h, x.distance(fit.centre));
      Assert(fit.h > 0, ExcInternalError());

      const unsigned int  m  = basis.size();
      const unsigned int  ns = n_stress<dim>;
      FullMatrix<double>  A(m, m), B(m, ns);
      std::vector<double> phi;
      // The monomials at the sampling points (for the stability check).
      std::vector<std::vector<double>> sample_phi;
      for (const auto &cell : cells)
        {
          const unsigned int index = cell->active_cell_index();
          for (unsigned int q = 0; q < sample_points[index].size(); ++q)
            {
              basis.values(Point<dim>((sample_points[index][q] - fit.centre) / fit.h), m, phi);
              for (unsigned int k = 0; k < m; ++k)
                {
                  for (unsigned int l = 0; l < m; ++l)
                    A(k, l) += phi[k] * phi[l];
                  for (unsigned int c = 0; c < ns; ++c)
                    B(k, c) +=
                      phi[k] *
                      sample_stress[index][q]
                                   [SymmetricTensor<2, dim>::unrolled_to_component_indices(c)];
                }
              sample_phi.push_back(phi);
            }
        }
      const unsigned int n_samples = sample_phi.size();

      // Where the fit is evaluated: at the vertex itself, at the other
      // support points of its cells (Q2), at the contact nodes' traction
      // samples on its cells, and, as a neighbour's fallback, at the other
      // vertices of its cells: all in the patch, which the vertices of its
      // cells span.
      std::vector<Point<dim>> patch_vertices;
      {
        std::vector<unsigned int> seen;
        for (const auto &cell : cells)
          for (const unsigned int v : cell->vertex_indices())
            if (std::find(seen.begin(), seen.end(), cell->vertex_index(v)) == seen.end())
              {
                seen.push_back(cell->vertex_index(v));
                patch_vertices.push_back(
                  Point<dim>((vertex_point[cell->vertex_index(v)] - fit.centre) / fit.h));
              }
      }

      // Highest degree (<= p) for which the sampling points determine the
      // polynomial stably. Degree 0 always works (there is at least one
      // sample; its fit is the mean, with Lebesgue constant 1).
      //
      // Full rank is not enough. In 3D a Q1 patch has one sampling point
      // per cell and 4 unknowns, and on a boundary of a locally refined mesh
      // the 4 cell centres of a face vertex (2 coarse cells and 2 children
      // of a refined neighbour, the centres of each pair on a line along the
      // edge between them) lie close to a plane: the normal matrix has full
      // rank (cond(S) ~ 1e4 on the curved two-cylinder mesh), but the slope
      // across that plane comes from the small offsets of the points, and
      // the fit's value at the vertex, off the plane, was hundreds of times
      // the sampled stresses (eta / |u|_E = 50 instead of 0.15). Hence the
      // degree is accepted only if the fit is stable on the patch: its
      // Lebesgue constant max_x sum_i |w_i(x)|, where sigma*(x) = sum_i w_i(x)
      // sigma_h(x_i) is the least-squares fit, taken over the vertices of the
      // patch cells, bounds the recovered stress anywhere it is used by that
      // multiple of the largest sampled one.
      unsigned int             d = degree;
      LAPACKFullMatrix<double> M;
      for (; d > 0; --d)
        {
          const unsigned int md = basis.size(d);
          if (n_samples < md)
            continue;
          LAPACKFullMatrix<double> Ad(md, md);
          for (unsigned int k = 0; k < md; ++k)
            for (unsigned int l = 0; l < md; ++l)
              Ad(k, l) = A(k, l);
          Ad.compute_svd();
          if (!(Ad.singular_value(md - 1) > rank_tolerance * Ad.singular_value(0)))
            continue;

          M.reinit(md, md);
          for (unsigned int k = 0; k < md; ++k)
            for (unsigned int l = 0; l < md; ++l)
              M(k, l) = A(k, l);
          M.compute_lu_factorization();
          double         lebesgue = 0;
          Vector<double> y(md);
          for (const Point<dim> &xi : patch_vertices)
            {
              // w_i(x) = phi(x_i) . A^-1 phi(x).
              basis.values(xi, md, phi);
              for (unsigned int k = 0; k < md; ++k)
                y(k) = phi[k];
              M.solve(y);
              double sum = 0;
              for (const std::vector<double> &phi_i : sample_phi)
                {
                  double w = 0;
                  for (unsigned int k = 0; k < md; ++k)
                    w += phi_i[k] * y(k);
                  sum += std::abs(w);
                }
              lebesgue = std::max(lebesgue, sum);
            }
          if (lebesgue <= stability_limit)
            break;
        }
      fit.kind              = (d == degree ? full_fit : reduced_fit);
      const unsigned int md = basis.size(d);
      if (d == 0)
        {
          // The mean (no stability check was made on this matrix).
          M.reinit(md, md);
          M(0, 0) = A(0, 0);
          M.compute_lu_factorization();
        }

      // The least-squares system, one right-hand side per stress component
      // (all components share the sampling matrix).
      Vector<double> column(md);
      fit.coefficients.assign(ns * m, 0.);
      for (unsigned int c = 0; c < ns; ++c)
        {
          for (unsigned int k = 0; k < md; ++k)
            column(k) = B(k, c);
          M.solve(column);
          for (unsigned int k = 0; k < md; ++k)
            fit.coefficients[c * m + k] = column(k);
        }
      return fit;
    }

    template <int dim>
    void
    SPREstimator<dim>::compute_vertex_fits()
    {
      const unsigned int n_coefficients = n_stress<dim> * basis.size();
      fit_stride                        = n_coefficients + 2; // + h, kind
      fe_fits = std::make_unique<FESystem<dim>>(FE_Q<dim>(1), n_slots * fit_stride);
      dof_fits.reinit(tria);
      dof_fits.distribute_dofs(*fe_fits);
      const IndexSet owned    = dof_fits.locally_owned_dofs();
      const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dof_fits);

      vertex_ref.assign(tria.n_vertices(), {DoFCellIt(), 0});
      for (const auto &cell : dof_fits.active_cell_iterators())
        if (!cell->is_artificial())
          for (const unsigned int v : cell->vertex_indices())
            vertex_ref[cell->vertex_index(v)] = {cell, v};

      TrilinosWrappers::MPI::Vector owned_fits(owned, comm);
      std::vector<bool>             visited(tria.n_vertices(), false);
      for (const auto &cell : dof_fits.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            {
              const unsigned int vertex = cell->vertex_index(v);
              if (visited[vertex])
                continue;
              visited[vertex] = true;
              // The owner of the vertex's DoFs fits its patches.
              if (!owned.is_element(cell->vertex_dof_index(v, 0)))
                continue;

              std::vector<types::material_id> here;
              for (const auto &other : vertex_cells[vertex])
                here.push_back(other->material_id());
              std::sort(here.begin(), here.end());
              here.erase(std::unique(here.begin(), here.end()), here.end());
              for (const types::material_id body : here)
                {
                  const PatchFit<dim> fit  = fit_patch(vertex, body);
                  const unsigned int  base = slot_of(body) * fit_stride;
                  for (unsigned int i = 0; i < n_coefficients; ++i)
                    owned_fits(cell->vertex_dof_index(v, base + i)) = fit.coefficients[i];
                  owned_fits(cell->vertex_dof_index(v, base + n_coefficients))     = fit.h;
                  owned_fits(cell->vertex_dof_index(v, base + n_coefficients + 1)) = fit.kind;
                }
            }
      owned_fits.compress(VectorOperation::insert);
      fits.reinit(owned, relevant, comm);
      fits = owned_fits;
    }

    template <int dim>
    PatchFit<dim>
    SPREstimator<dim>::read_fit(const unsigned int vertex, const types::material_id body) const
    {
      const unsigned int n_coefficients = n_stress<dim> * basis.size();
      const auto &[cell, v]             = vertex_ref[vertex];
      Assert(cell.state() == IteratorState::valid, ExcInternalError());
      const unsigned int base = slot_of(body) * fit_stride;

      PatchFit<dim> fit;
      fit.centre = vertex_point[vertex];
      fit.coefficients.resize(n_coefficients);
      for (unsigned int i = 0; i < n_coefficients; ++i)
        fit.coefficients[i] = fits(cell->vertex_dof_index(v, base + i));
      fit.h    = fits(cell->vertex_dof_index(v, base + n_coefficients));
      fit.kind = static_cast<unsigned int>(
        std::lround(fits(cell->vertex_dof_index(v, base + n_coefficients + 1))));
      return fit;
    }

    template <int dim>
    const std::vector<PatchFit<dim>> &
    SPREstimator<dim>::effective_fit(const unsigned int vertex, const types::material_id body)
    {
      const auto key = std::make_pair(vertex, body);
      const auto it  = effective_cache.find(key);
      if (it != effective_cache.end())
        return it->second;

      std::vector<PatchFit<dim>> result;
      PatchFit<dim>              own = read_fit(vertex, body);
      AssertThrow(own.kind != no_fit,
                  ExcMessage("StressRecovery: internal error, a vertex patch was not fitted."));
      if (own.kind == full_fit)
        result.push_back(std::move(own));
      else
        {
          // Boundary fallback (Zienkiewicz-Zhu): a vertex whose own patch cannot
          // determine a degree-p polynomial takes the mean of the full fits of
          // its neighbouring vertices (the other vertices of its patch cells),
          // evaluated at the point in question.
          std::vector<unsigned int> neighbours;
          for (const auto &cell : vertex_cells[vertex])
            if (cell->material_id() == body)
              for (const unsigned int v : cell->vertex_indices())
                if (cell->vertex_index(v) != vertex)
                  neighbours.push_back(cell->vertex_index(v));
          std::sort(neighbours.begin(), neighbours.end());
          neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
          for (const unsigned int w : neighbours)
            {
              PatchFit<dim> fit = read_fit(w, body);
              if (fit.kind == full_fit)
                result.push_back(std::move(fit));
            }
          // No neighbour has a full fit either (a body of very few cells): keep
          // the lower-degree fit of the vertex's own patch.
          if (result.empty())
            result.push_back(std::move(own));
        }
      return effective_cache.emplace(key, std::move(result)).first->second;
    }

    // The recovered value at a contact node solves the node's patch problem
    // augmented by the traction condition: minimise
    //   |sigma* - sigma_fit|^2 + alpha_n (n.(r))^2 + alpha_t |(I - n n) r|^2,
    //   r = t - mean of sigma* n over the node's support,
    // over constant shifts sigma* = sigma_fit + delta of the node's fitted
    // polynomial (Frobenius norm, which counts a shear component twice). The
    // minimiser changes only the traction components:
    //   delta = alpha_n / (1 + alpha_n) (n.r) n(x)n
    //         + sum_t alpha_t / (2 + alpha_t) (t.r) (n(x)t + t(x)n).
    // For a finite-strain body the recovered field is the Cauchy stress at
    // the reference points, while the contact traction (recovery_tractions()
    // in contact_problem_refinement.cc: the node's force over its reference
    // int N_j ds, with either kinematics) is per reference area. By Nanson,
    // sigma n da = J sigma F^-T N dA, so the condition compares J sigma*
    // F^-T N, F = I + grad u_h of the node's cell nearest to the sample.
    template <int dim>
    std::vector<Tensor<1, dim>>
    SPREstimator<dim>::traction_vectors(const std::size_t j) const
    {
      const ContactNodeTraction<dim> &node = contact_nodes[j];
      std::vector<std::pair<Point<dim>, Tensor<1, dim>>> points;
      if (node.samples.empty())
        points.emplace_back(node.location, node.normal / node.normal.norm());
      for (const TractionSample<dim> &q : node.samples)
        points.emplace_back(q.point, q.normal / q.normal.norm());
      std::vector<Tensor<1, dim>> vectors;
      for (const auto &point : points)
        vectors.push_back(point.second);
      if (node_cells[j].empty() ||
          materials.constants(node_cells[j][0]->material_id()).model == ElasticModel::linear)
        return vectors;

      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<2, dim>>      gradient(1);
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          // The cell of the node's body whose unit point of the sample is
          // nearest its unit cell (ties to the lower CellId, so that every
          // partition picks the same).
          double     distance = std::numeric_limits<double>::infinity();
          CellIt     nearest;
          Point<dim> unit;
          for (const CellIt &cell : node_cells[j])
            try
              {
                const Point<dim> p = mapping.transform_real_to_unit_cell(cell, points[i].first);
                const double     d = GeometryInfo<dim>::distance_to_unit_cell(p);
                if (d < distance || (d == distance && cell->id() < nearest->id()))
                  std::tie(distance, nearest, unit) = std::make_tuple(d, cell, p);
              }
            catch (const typename Mapping<dim>::ExcTransformationFailed &)
              {}
          AssertThrow(std::isfinite(distance),
                      ExcMessage("StressRecovery: a traction sample of a contact node lies "
                                 "in none of the node's cells."));
          FEValues<dim> fe_values(mapping, dof_handler.get_fe(),
                                  Quadrature<dim>(GeometryInfo<dim>::project_to_unit_cell(unit)),
                                  update_gradients);
          fe_values.reinit(DoFCellIt(&tria, nearest->level(), nearest->index(), &dof_handler));
          fe_values[displacement].get_function_gradients(solution, gradient);
          Tensor<2, dim> F = gradient[0];
          for (unsigned int d = 0; d < dim; ++d)
            F[d][d] += 1.;
          vectors[i] = determinant(F) * (transpose(invert(F)) * points[i].second);
        }
      return vectors;
    }

    // The shift is applied to this node's value only: a contact condition in
    // the fits of neighbouring patches (as first implemented) fitted the
    // pressure's variation along the slightly curved surface with the
    // polynomial's gradient across it, and overestimated the error several
    // times on coarse contact zones.
    template <int dim>
    template <typename Function>
    SymmetricTensor<2, dim>
    SPREstimator<dim>::traction_correction(const std::size_t j, const Function &fitted) const
    {
      const ContactNodeTraction<dim>   &node    = contact_nodes[j];
      const std::vector<Tensor<1, dim>> vectors = traction_vectors(j);
      Tensor<1, dim>                    mean_traction;
      if (node.samples.empty())
        mean_traction = fitted(node.location) * vectors[0];
      else
        {
          double total = 0.;
          for (unsigned int i = 0; i < node.samples.size(); ++i)
            {
              const TractionSample<dim> &q = node.samples[i];
              mean_traction += q.weight * (fitted(q.point) * vectors[i]);
              total += q.weight;
            }
          AssertThrow(std::abs(total) > 0.,
                      ExcMessage("StressRecovery: the traction samples of a contact node "
                                 "have zero total weight."));
          mean_traction /= total;
        }
      const Tensor<1, dim> r = node.traction - mean_traction;
      const Tensor<1, dim> n = node.normal / node.normal.norm();

      const double alpha_n = settings.penalty_normal, alpha_t = settings.penalty_tangential;
      SymmetricTensor<2, dim> delta =
        (alpha_n / (1. + alpha_n) * (n * r)) * symmetrize(outer_product(n, n));
      for (const Tensor<1, dim> &t : tangents<dim>(n))
        delta += (alpha_t / (2. + alpha_t) * (t * r) * 2.) * symmetrize(outer_product(n, t));
      return delta;
    }

    template <int dim>
    void
    SPREstimator<dim>::recover_nodal_values()
    {
      fe_recovered = std::make_unique<FESystem<dim>>(fe_q, n_slots * n_stress<dim>);
      dof_recovered.reinit(tria);
      dof_recovered.distribute_dofs(*fe_recovered);
      const IndexSet owned    = dof_recovered.locally_owned_dofs();
      const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dof_recovered);

      AffineConstraints<double> hanging_nodes;
      hanging_nodes.reinit(relevant);
      DoFTools::make_hanging_node_constraints(dof_recovered, hanging_nodes);
      hanging_nodes.close();

      // The cell vertices that determine the value at each support point of
      // FE_Q(p): those of the vertex, edge, face or cell it belongs to.
      const unsigned int                     n_scalar = fe_q.n_dofs_per_cell();
      std::vector<std::vector<unsigned int>> object_vertices(n_scalar);
      for (unsigned int k = 0; k < n_scalar; ++k)
        {
          if (k < fe_q.get_first_line_index())
            object_vertices[k] = {k / fe_q.n_dofs_per_vertex()};
          else if (k < fe_q.get_first_quad_index(0))
            {
              const unsigned int line = (k - fe_q.get_first_line_index()) / fe_q.n_dofs_per_line();
              object_vertices[k]      = {GeometryInfo<dim>::line_to_cell_vertices(line, 0),
                                         GeometryInfo<dim>::line_to_cell_vertices(line, 1)};
            }
          else if (dim == 3 && k < fe_q.get_first_hex_index())
            {
              const unsigned int face =
                (k - fe_q.get_first_quad_index(0)) / fe_q.n_dofs_per_quad(0);
              for (unsigned int i = 0; i < GeometryInfo<dim>::vertices_per_face; ++i)
                object_vertices[k].push_back(GeometryInfo<dim>::face_to_cell_vertices(face, i));
            }
          else
            for (const unsigned int v : GeometryInfo<dim>::vertex_indices())
              object_vertices[k].push_back(v);
        }
      const std::vector<Point<dim>> &unit_points = fe_q.get_unit_support_points();

      // The contact node at a support point, keyed by the DoF of the first
      // stress component of the slave body's slot there (a DoF may be
      // reached from a cell without the slave face, so the match found on
      // the cells with it is recorded per DoF).
      std::map<types::global_dof_index, std::size_t> contact_of_dof;
      std::vector<types::global_dof_index>           dof_indices(fe_recovered->n_dofs_per_cell());
      for (const auto &dof_cell : dof_recovered.active_cell_iterators())
        if (!dof_cell->is_artificial() && !cell_contacts[dof_cell->active_cell_index()].empty())
          {
            dof_cell->get_dof_indices(dof_indices);
            const unsigned int slot = slot_of(dof_cell->material_id());
            for (const auto &[k, j] : cell_contacts[dof_cell->active_cell_index()])
              contact_of_dof.emplace(
                dof_indices[fe_recovered->component_to_system_index(slot * n_stress<dim>, k)], j);
          }

      // Recovered stress per contact node, summed over the owners of its
      // support point (normally one) and averaged below.
      node_stresses.assign(contact_nodes.size(), SymmetricTensor<2, dim>());
      std::vector<double> node_hits(contact_nodes.size(), 0.);

      TrilinosWrappers::MPI::Vector owned_values(owned, comm);
      std::vector<bool>             done(owned.n_elements(), false);
      for (const auto &dof_cell : dof_recovered.active_cell_iterators())
        if (dof_cell->is_locally_owned())
          {
            const CellIt cell(&tria, dof_cell->level(), dof_cell->index());
            dof_cell->get_dof_indices(dof_indices);
            // Values per (support point, slot), computed on first use.
            std::map<std::pair<unsigned int, unsigned int>, SymmetricTensor<2, dim>> values;
            for (unsigned int i = 0; i < dof_indices.size(); ++i)
              {
                const types::global_dof_index index = dof_indices[i];
                if (!owned.is_element(index))
                  continue;
                const auto local = owned.index_within_set(index);
                if (done[local])
                  continue;
                done[local] = true;
                if (hanging_nodes.is_constrained(index))
                  continue;

                const auto [component, k] = fe_recovered->system_to_component_index(i);
                const unsigned int slot   = component / n_stress<dim>;
                const unsigned int c      = component % n_stress<dim>;
                const auto         key    = std::make_pair(k, slot);
                auto               found  = values.find(key);
                if (found == values.end())
                  {
                    const types::material_id body =
                      (n_slots == 1 ? cell->material_id() : bodies[slot]);
                    bool present = true;
                    for (const unsigned int v : object_vertices[k])
                      present = present && has_body(cell->vertex_index(v), body);
                    SymmetricTensor<2, dim> value;
                    // A slot of another body at a shared point gets its own
                    // body's value; slots of bodies absent here are unused (0).
                    if (present)
                      {
                        // The recovered polynomial of this support point: the
                        // mean of the fits of its object's vertices.
                        const auto fitted = [&](const Point<dim> &x) {
                          SymmetricTensor<2, dim> sigma;
                          for (const unsigned int v : object_vertices[k])
                            {
                              const auto &fits_v = effective_fit(cell->vertex_index(v), body);
                              for (const PatchFit<dim> &fit : fits_v)
                                sigma += evaluate(fit, basis, x) /
                                         double(fits_v.size() * object_vertices[k].size());
                            }
                          return sigma;
                        };
                        const Point<dim> x =
                          (k < GeometryInfo<dim>::vertices_per_cell ?
                             vertex_point[cell->vertex_index(k)] :
                             mapping.transform_unit_to_real_cell(cell, unit_points[k]));
                        value              = fitted(x);
                        const auto contact = contact_of_dof.find(
                          dof_indices[fe_recovered->component_to_system_index(slot * n_stress<dim>,
                                                                              k)]);
                        if (contact != contact_of_dof.end())
                          {
                            const ContactNodeTraction<dim> &node = contact_nodes[contact->second];
                            if (settings.contact_terms && node.imposed)
                              value += traction_correction(contact->second, fitted);
                            node_stresses[contact->second] += value;
                            node_hits[contact->second] += 1.;
                          }
                      }
                    found = values.emplace(key, value).first;
                  }
                owned_values(index) =
                  found->second[SymmetricTensor<2, dim>::unrolled_to_component_indices(c)];
              }
          }
      owned_values.compress(VectorOperation::insert);
      {
        // One reduction: the stress components and the hit count per node.
        constexpr unsigned int stride = n_stress<dim> + 1;
        std::vector<double>    packed;
        packed.reserve(contact_nodes.size() * stride);
        for (std::size_t j = 0; j < contact_nodes.size(); ++j)
          {
            for (unsigned int c = 0; c < n_stress<dim>; ++c)
              packed.push_back(
                node_stresses[j][SymmetricTensor<2, dim>::unrolled_to_component_indices(c)]);
            packed.push_back(node_hits[j]);
          }
        Utilities::MPI::sum(packed, comm, packed);
        for (std::size_t j = 0; j < contact_nodes.size(); ++j)
          {
            const double hits = packed[j * stride + n_stress<dim>];
            for (unsigned int c = 0; c < n_stress<dim>; ++c)
              node_stresses[j][SymmetricTensor<2, dim>::unrolled_to_component_indices(c)] =
                hits > 0. ? packed[j * stride + c] / hits : 0.;
          }
      }
      hanging_nodes.distribute(owned_values);
      recovered.reinit(owned, relevant, comm);
      recovered = owned_values;
    }

    template <int dim>
    typename SPREstimator<dim>::Result
    SPREstimator<dim>::integrate() const
    {
      Result result;
      result.cell_indicators.reinit(tria.n_active_cells());

      const QGauss<dim> quadrature(degree + 2);
      FEValues<dim>     fe_values(mapping, dof_handler.get_fe(), quadrature,
                                  update_gradients | update_JxW_values);
      FEValues<dim>     fe_values_recovered(mapping, *fe_recovered, quadrature, update_values);
      std::vector<SymmetricTensor<2, dim>> strains(quadrature.size()), stresses;
      std::vector<Vector<double>>          recovered_values(quadrature.size(),
                                                            Vector<double>(fe_recovered->n_components()));

      double error_squared = 0, energy = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const DoFCellIt cell_recovered(&tria, cell->level(), cell->index(), &dof_recovered);
            fe_values.reinit(cell);
            fe_values_recovered.reinit(cell_recovered);
            fe_stresses(cell, fe_values, strains, stresses);
            fe_values_recovered.get_function_values(recovered, recovered_values);

            const types::material_id body        = cell->material_id();
            const unsigned int       base        = slot_of(body) * n_stress<dim>;
            double                   eta_squared = 0;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const SymmetricTensor<2, dim> &sigma_h = stresses[q];
                SymmetricTensor<2, dim>        sigma_star;
                for (unsigned int c = 0; c < n_stress<dim>; ++c)
                  sigma_star[SymmetricTensor<2, dim>::unrolled_to_component_indices(c)] =
                    recovered_values[q](base + c);
                const SymmetricTensor<2, dim> difference = sigma_star - sigma_h;
                eta_squared +=
                  (difference * materials.compliance(body, difference)) * fe_values.JxW(q);
                energy += (sigma_h * strains[q]) * fe_values.JxW(q);
              }
            result.cell_indicators(cell->active_cell_index()) = std::sqrt(eta_squared);
            error_squared += eta_squared;
          }

      error_squared               = Utilities::MPI::sum(error_squared, comm);
      energy                      = Utilities::MPI::sum(energy, comm);
      result.estimated_error      = std::sqrt(error_squared);
      result.solution_energy_norm = std::sqrt(std::max(energy, 0.));
      if (result.solution_energy_norm > 0)
        result.relative_error = result.estimated_error / result.solution_energy_norm;
      else
        result.relative_error =
          (result.estimated_error > 0 ? std::numeric_limits<double>::infinity() : 0.);
      return result;
    }

    template <int dim>
    typename SPREstimator<dim>::Result
    SPREstimator<dim>::run()
    {
      collect_topology();
      sample_stresses();
      match_contact_nodes();
      compute_vertex_fits();
      recover_nodal_values();
      Result result        = integrate();
      result.node_stresses = std::move(node_stresses);
      return result;
    }
  } // namespace

  template <int dim>
  typename StressRecovery<dim>::Result
  StressRecovery<dim>::estimate(const Mapping<dim>                          &mapping,
                                const DoFHandler<dim>                       &dof_handler,
                                const TrilinosWrappers::MPI::Vector         &solution,
                                const Materials<dim>                        &materials,
                                const std::vector<ContactNodeTraction<dim>> &contact_nodes,
                                const Settings                              &settings,
                                VolumetricProjection<dim>                   *volumetric)
  {
    SPREstimator<dim> estimator(mapping, dof_handler, solution, materials, contact_nodes, settings,
                                volumetric);
    return estimator.run();
  }

  template class StressRecovery<2>;
  template class StressRecovery<3>;
} // namespace contact_fem
