// The contact surfaces of all pairs, gathered on every rank, with the search
// and the mortar operators of the slave nodes.
#ifndef contact_fem_contact_interface_h
#define contact_fem_contact_interface_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi_noncontiguous_partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/material/material.h>
#include <contact_fem/contact/mortar_kernel.h>
#include <contact_fem/contact/contact_parameters.h>

#include <array>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace contact_fem
{
  /// A check of the contact surfaces' geometry failed on some rank (a
  /// slave face that its facing master faces do not tile, ...): fatal on
  /// the configuration a step starts from, but on a Newton iterate of
  /// current kinematics a property of that iterate, and the step is split
  /// (ContactProblem::newton_iterations()).
  struct GeometryFailure : public std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  using namespace dealii;

  /**
   * The slave and master surfaces of every contact pair.
   *
   * The surfaces are lower-dimensional, so each rank gathers all of them
   * (faces, reference coordinates and DoF indices of their nodes) once per
   * mesh. The narrow phase and the mortar integration of the slave faces
   * that have candidate masters are shared out over the ranks by their
   * cost (the contact zone need not follow the partition of the cells);
   * the segments are exchanged, and every rank
   * assembles the operators of the whole interface from them in face
   * order: every rank then knows every constraint that touches its DoFs,
   * and the result does not depend on the partition.
   *
   * Search and mortar integration run on the configuration X + u the
   * caller gives (the reference configuration with Contact/Kinematics =
   * small, the start of every load step with updated); the gap is then
   * linear in the displacement. surface_distances() checks a converged
   * state against the whole master surface, independently of the operators.
   *
   * Written once over the dimension, with the face kernel of
   * Mortar::Kernel<dim> (mortar_kernel.h): line faces of degree 1 or 2 in
   * 2D, quadrilateral faces of degree 1 or 2 in 3D. In both, Q1 on a
   * quadratic mapping has faces of geometry degree 2
   * (Face::geometry_points) with the linear or bilinear shapes of the
   * element. Only the tiling check of the segmentation differs by
   * dimension (check_tiling()).
   *
   * Hanging vertices (3D adaptive meshes: a node on the edge of a coarser
   * neighbour face) carry no multiplier: the multiplier space is that of
   * the constrained trace, whose nodes (owners) are the regular slave
   * nodes. On a face with hanging vertices the dual functions of its
   * owners are built biorthogonal to the owners' trace functions there
   * (add_constrained_face()), so D stays diagonal and exact for every
   * displacement of the constrained space, and the functions still sum to
   * one (a uniform pressure stays exact). Master columns of hanging
   * vertices go to their parents with the hanging-node weights, so no
   * constraint refers to a hanging DoF.
   *
   * Implemented in source/contact/contact_interface.cc (set-up, hanging
   * vertices, operators), source/contact/contact_interface_search.cc (search
   * and integration, surface distances) and
   * source/contact/contact_interface_tiling.cc (the tiling checks).
   */
  template <int dim>
  class ContactInterface
  {
  public:
    /// The face geometry of the mortar kernel: Mortar::LineFace (2D) or
    /// Mortar::QuadFace (3D).
    using FaceGeometry = typename Mortar::Kernel<dim>::Face;

    /// A node (support point) of a contact surface.
    struct Node
    {
      Point<dim>                               reference;
      std::array<types::global_dof_index, dim> dofs;
      std::array<bool, dim>                    fixed; ///< Dirichlet component
      /// Per axis d: the node lies on a symmetry plane normal to e_d (a
      /// support fixes component d on a flat boundary face normal to e_d
      /// through the node and leaves the other components free there, a
      /// roller). Its nodal normal has component d removed: the normal of
      /// the whole, mirror-symmetric surface (find_symmetry_planes()).
      std::array<bool, dim> symmetry_plane{};
      bool                  slave  = false;
      bool                  master = false;
      /// A hanging vertex of the surface (a node on the edge of a coarser
      /// neighbour face, 3D adaptive meshes): the nodes and weights its
      /// displacement is interpolated from. Empty for a regular node.
      std::vector<std::pair<unsigned int, double>> parents;
    };

    /// A face of a contact surface.
    struct Face
    {
      /// Mortar::LineFace (2D) or Mortar::QuadFace (3D) node order.
      std::vector<unsigned int> nodes;
      /// Reference positions of geometry nodes without DoFs of a degree-1
      /// face on a quadratic mapping, from the mapping: in 2D the midpoint,
      /// in 3D the four edge midpoints and the centre (nodes 4-8 of
      /// Mortar::QuadFace). They move with the (bi)linear interpolation of
      /// the vertex displacements (face_geometry()). Empty if isoparametric.
      std::vector<Point<dim>> geometry_points;
      double                  orientation; ///< makes the rotated tangent point outward
      unsigned int            pair;
      bool                    slave;
      double                  youngs_modulus;
      double                  poisson_ratio;
    };

    /// Mortar data of one slave node at the current search.
    struct SlaveNode
    {
      unsigned int   node;
      unsigned int   pair;
      Tensor<1, dim> normal; ///< unit, out of the slave body
      /// Unit normal of the interface the two surfaces share once pressed
      /// together, out of the slave: the mean of the slave normal and the
      /// reversed master normal at the projection, weighted by the
      /// plane-strain moduli (each surface deflects in proportion to its
      /// compliance, so a rigid master keeps its own normal and equal
      /// bodies meet half-way). The frame of the frictional conditions.
      Tensor<1, dim> interface_normal;
      double         D         = 0.; ///< int over the overlap of Phi_j
      double         full_area = 0.; ///< int of N_j over the adjacent slave faces
      double         size      = 0.; ///< nodal element size h_j
      /// n_j . (int Phi_j (x_master - x_slave) ds - (sum_l M_jl x_l - D_j x_j))
      /// at the search configuration: the part of the weighted gap that the
      /// nodal form misses where the geometry is curved beyond the element
      /// degree (the sag of a Q1 face on a quadratic mapping); zero up to
      /// quadrature for isoparametric faces.
      double                                       curvature_gap = 0.;
      std::vector<std::pair<unsigned int, double>> M;              ///< (master node, M_jl)
      bool                                         paired = false; ///< has a master projection
    };

    /**
     * The consistent linearisation of one paired slave node j at the
     * configuration of the last search (Contact/Kinematics = current, 2D):
     * derivatives with respect to the displacement DoFs of its patch (its
     * slave faces, the slave faces next to them, their masters).
     */
    struct LinearisedNode
    {
      /// The DoFs the derivatives refer to.
      std::vector<types::global_dof_index> dofs;
      /// d G_j / du, G_j = n_j . int Phi_j (x_master - x_slave) = D_j g_j.
      std::vector<double> gap;
      /// d D_j / du (the penalty's pressure is eps G_j / D_j).
      std::vector<double> D;
      /// d f_j / du per DoF of the contact force per unit pressure f_j
      /// (-D_j n_j on the slave node, +M_jl n_j on master l): (row, values
      /// at dofs).
      std::vector<std::pair<types::global_dof_index, std::vector<double>>> force;
      /// Per global component c, the same for the force of a held unit
      /// tangential traction t = e_c (D_j t on the slave, -M_jl t on master
      /// l), t kept in the tangent plane as n_j turns: dt = -(t . dn_j) n_j
      /// (in 2D the turn of the tangent). The rows of @p force. Frictional
      /// only (linearise()).
      std::array<std::vector<std::pair<types::global_dof_index, std::vector<double>>>, dim>
        tangent_force;
      /// d n_j / du, per component (frictional only).
      std::array<std::vector<double>, dim> normal;
      /// d (D_j x_j - sum_l M_jl x_l) / du with the positions x held: the
      /// operators' part of the objective slip, per component (frictional
      /// only).
      std::array<std::vector<double>, dim> operators;
      /// d n_int / du of SlaveNode::interface_normal, per component
      /// (frictional only): from dn_j, dM_jl and the derivatives of the
      /// master nodal normals n_l (averaged over the master faces at l, as
      /// the slave's), through the weighted mean and its normalisation.
      std::array<std::vector<double>, dim> interface_normal;
      /// As @p force with n_int in place of n_j: d (-D_j n_int, M_jl n_int)
      /// / du, same rows (frictional only).
      std::vector<std::pair<types::global_dof_index, std::vector<double>>> interface_force;
      /// As @p tangent_force with the held traction kept in the tangent
      /// plane of n_int: dt = -(t . dn_int) n_int (frictional only).
      std::array<std::vector<std::pair<types::global_dof_index, std::vector<double>>>, dim>
        interface_tangent_force;
    };

    /// Interface statistics of the last search, per pair.
    struct PairStatistics
    {
      double mean_slave_size = 0., mean_master_size = 0.;
      double slave_modulus = 0., master_modulus = 0.;
    };

    /**
     * Collects the faces of @p pairs from all ranks. @p dirichlet holds the
     * Dirichlet constraints only (to flag fixed components), @p hanging the
     * closed hanging-node constraints of the locally relevant DoFs.
     * @p moving_supports are boundaries whose prescribed displacement varies
     * along them: never symmetry planes.
     */
    void
    initialize(const MappingQ<dim>                  &mapping,
               const DoFHandler<dim>                &dof_handler,
               const std::vector<ContactPair>       &pairs,
               const AffineConstraints<double>      &dirichlet,
               const AffineConstraints<double>      &hanging,
               const Materials<dim>                 &materials,
               const MPI_Comm                        comm,
               const std::set<types::boundary_id>   &moving_supports = {});

    /// The communicator of the ranks sharing the interface.
    MPI_Comm
    communicator() const
    {
      return mpi_communicator;
    }

    /// Sorted DoF indices of all interface nodes.
    const std::vector<types::global_dof_index> &
    dofs() const
    {
      return interface_dofs;
    }

    /// Position of @p dof in dofs().
    unsigned int
    position(const types::global_dof_index dof) const
    {
      return dof_position.at(dof);
    }

    /// Whether some node lies on the slave surface of one pair and on the
    /// master surface of another: a chain of pairs passes through it, and
    /// its residual holds both pairs' forces (recovered pass by pass,
    /// ContactFormulation::recover_through_chains()). Not collective (every
    /// rank holds the whole interface).
    bool
    has_chained_nodes() const
    {
      for (const auto &node : nodes)
        if (node.slave && node.master)
          return true;
      return false;
    }

    /// Whether the DoF at @p position of dofs() is a Dirichlet component
    /// (Node::fixed), on every rank.
    bool
    dof_fixed(const unsigned int position) const
    {
      return fixed_positions[position];
    }

    /// The number of slave nodes that carry a multiplier (first) and of
    /// hanging slave vertices (second), counted at initialize(); not
    /// collective.
    std::pair<unsigned int, unsigned int>
    count_slave_nodes() const
    {
      return slave_node_counts;
    }

    /// The values of @p v at dofs(), from their owners, on every rank.
    /// Collective.
    std::vector<double>
    gather(const TrilinosWrappers::MPI::Vector &v) const;

    /// The values of @p value_on_owner at dofs(), evaluated by the owner of
    /// each DoF, on every rank: each rank evaluates the DoFs it owns and
    /// imports the others from their owners (point to point, the pattern
    /// built once per mesh). Collective.
    std::vector<double>
    gather(const std::function<double(types::global_dof_index)> &value_on_owner) const;

    /// Whether this rank owns the row of slave node @p s (its x DoF): it
    /// assembles it and makes the node's decisions (active set,
    /// multipliers), which the others receive (share_node_values()).
    bool
    owns_row(const SlaveNode &s) const
    {
      return owned_dofs.is_element(nodes[s.node].dofs[0]);
    }

    /**
     * Per-node values of the formulation's state (@p fields, each indexed
     * by node) of the regular slave nodes, decided by the owners of their
     * rows (owns_row()), copied to the other ranks: to the ghosts (slave
     * nodes with a locally relevant DoF whose row another rank owns) point
     * to point from their owners; to the other slave nodes (the readers
     * that still read the whole interface: the residuals' sums in node
     * order, the constraint lines of every rank, the postprocessors) by an
     * all-gather of the owned nodes where one of the first @p n_key fields
     * is not +0 (the contact zone), the others set to +0. Exact copies.
     * Collective.
     */
    void
    share_node_values(const std::vector<std::vector<double> *> &fields,
                      const unsigned int                        n_key) const;

    /**
     * The sum over the slave nodes, in their order (slave_nodes), of terms
     * computed by the owners of their rows: @p terms holds this rank's as
     * (index into slave_nodes, term), in that order, any number per node.
     * Every rank gets the serial sum bit for bit: the terms other than +0
     * all-gathered and added in node order, each node's in its order (a +0
     * term leaves a sum of terms >= +0 as it is, so only sums of such terms
     * may skip them), added to @p start (the same on every rank, not -0):
     * index any key whose order is the serial sum's (the position in dofs()
     * too). Collective.
     */
    double
    sum_in_node_order(const std::vector<std::pair<unsigned int, double>> &terms,
                      const double                                        start = 0.) const;

    /// A term of a contact force: @p value at the DoF dofs()[@p position],
    /// from the slave node whose @p key orders it in the serial loop (its
    /// index into slave_nodes, plus a multiple of their number for a later
    /// loop over them).
    struct ForceTerm
    {
      double       key;
      unsigned int position;
      double       value;
    };

    /**
     * The contact force at dofs() from the terms of the slave nodes whose
     * rows this rank owns (@p terms, in the loop's order): each term goes
     * to the owner of its DoF, which adds the terms it receives in the
     * order of their keys (a node's terms come from one rank, in order);
     * every rank then gets the owners' sums (gather()). Every value is the
     * serial loop's bit for bit, and no rank needs the slave nodes coupled
     * to its master DoFs (issue 32 item 1). Collective, unless
     * @p every_node_here: @p terms are then those of every slave node,
     * added here in their order (the check of the held state).
     */
    std::vector<double>
    sum_forces(const std::vector<ForceTerm> &terms, const bool every_node_here = false) const;

    /**
     * Whether slave node @p s is one whose state the contact forces at
     * this rank's locally relevant DoFs would need if they were summed
     * here: its row is owned here, or it or a master node of its M has a
     * locally relevant DoF. Counted only (HeldCounts::closed_ghosts): the
     * forces are summed by the owners of the DoFs (sum_forces()), which
     * needs only the owned rows. Set at each search. Not collective.
     */
    bool
    holds_state(const SlaveNode &s) const
    {
      return state_held[s.node];
    }

    /**
     * The check of the held state (environment variable
     * CONTACT_FEM_CHECK_HELD_STATE set): @p held, the contact force at dofs()
     * from the owned rows summed by the DoFs' owners (sum_forces()), must
     * equal @p full, summed here over every slave node, bit for bit at
     * every interface DoF; throws otherwise. Counts the locally relevant
     * DoFs compared and the other DoFs where the two differ (none once it
     * returns) for count_held(). Not collective.
     */
    void
    check_held_forces(const std::vector<double> &held, const std::vector<double> &full) const;

    /// Whether CONTACT_FEM_CHECK_HELD_STATE is set: the readers of the held
    /// state compute their results from every node too and compare.
    static bool
    checking_held_state();

    /**
     * Whether CONTACT_FEM_CHECK_HELD_SURFACE is set: a rehearsal of the
     * surfaces held per rank (issue 32 item 1). After each search, the
     * slave nodes off the faces within reach of this rank's own faces
     * (HeldCounts::faces_within_reach, what a rank will hold) get NaN in
     * every number of their SlaveNode, and share_node_values() gives NaN to
     * those nodes' state instead of the zone's values. A reader that still
     * reads the whole surface then prints NaN or fails; one that reads only
     * what its rank will hold gives the same output. Serial runs hold
     * everything and are not changed.
     */
    static bool
    checking_held_surface();

    /**
     * Whether this rank stores the constraint lines of slave node @p s (the
     * gap lines, alm's candidate lines, the stick and slip lines): it has
     * a locally relevant DoF or one of the linearised patch of a row owned
     * here, or it is a master of a node held so (repeatedly: close() chains
     * a line through a master DoF that is another pair's line DoF). The
     * lines at the locally relevant DoFs are then those of every node, bit
     * for bit (check_held_lines()). Set at each search and by linearise().
     * Not collective.
     */
    bool
    holds_line(const SlaveNode &s) const
    {
      return line_held[s.node];
    }

    /// The DoFs a rank's constraints may store lines at: the locally
    /// relevant DoFs and every DoF of the nodes held for the lines
    /// (holds_line()) and of their masters. Set with holds_line().
    const IndexSet &
    line_dofs() const
    {
      return held_line_dofs;
    }

    /**
     * Closes @p lines, the DoFs a rank's constraints store lines at, under
     * the masters of @p surfaces together (the non-null ones: a chain may
     * cross from the contact to the tied interface): adds every DoF of the
     * masters of each slave node and of the parents of each hanging node
     * with a DoF in @p lines, until nothing is added (close() resolves a
     * line through the lines at its masters). Not collective.
     */
    static void
    close_line_dofs(IndexSet &lines, const std::vector<const ContactInterface<dim> *> &surfaces);

    /**
     * The check of the held lines (checking_held_state()): @p held, the
     * closed constraints stored at line_dofs(), must have at every locally
     * relevant DoF the line of @p full, stored at every interface DoF: the
     * same entries in the same order and the same inhomogeneity, bit for
     * bit; throws otherwise. Counts the DoFs compared and the lines of
     * @p full the held ones left out for count_held(). Collective.
     */
    void
    check_held_lines(const AffineConstraints<double> &held,
                     const AffineConstraints<double> &full) const;

    /// The numbers of regular slave nodes whose row this rank owns (first)
    /// and of its ghosts (second); share_node_values().
    std::pair<unsigned int, unsigned int>
    count_held_rows() const
    {
      return {static_cast<unsigned int>(owned_row_nodes.size()),
              static_cast<unsigned int>(ghost_row_nodes.size())};
    }

    /// What this rank holds of the interface (per-rank memory of the
    /// contact data; summary.json "held_per_rank"). Not collective.
    struct HeldCounts
    {
      unsigned int faces                = 0; ///< faces (slave and master)
      unsigned int slave_nodes          = 0; ///< slave_nodes (with their operators)
      unsigned int rows_owned           = 0; ///< count_held_rows().first
      unsigned int row_ghosts           = 0; ///< count_held_rows().second
      unsigned int interface_dofs       = 0; ///< dofs() (gather()'s result)
      unsigned int interface_dofs_owned = 0;
      /// The most node states one share_node_values() received besides
      /// the ghosts' (the contact zone all-gathered), since initialize().
      unsigned int zone_nodes_received = 0;
      /// Slave nodes whose state is held (holds_state()) but whose row
      /// another rank owns: the ghosts closed under M at the last search.
      unsigned int closed_ghosts = 0;
      /// With checking_held_state(): the interface DoFs at which the held
      /// contact forces were compared with the full ones (the largest
      /// count of one call), and the most DoFs outside the locally relevant
      /// ones at which they differed (nodes the held loop left out).
      unsigned int check_dofs_compared = 0, check_dofs_left_out = 0;
      /// Slave nodes whose lines are held (holds_line()) and the size of
      /// line_dofs(), at the last search.
      unsigned int line_nodes = 0, line_dofs = 0;
      /// With checking_held_state(): the locally relevant DoFs at which
      /// the held lines were compared with the full ones, and the lines of
      /// the full constraints the held ones left out (the most of one
      /// call).
      unsigned int check_lines_compared = 0, check_lines_left_out = 0;
      /// The faces a rank would hold if it held only those within reach
      /// of its own (the memory clause of issue 32 item 1, not yet done):
      /// its slave faces, the master faces their search boxes (enlarged by
      /// the search's reach) meet, and the faces sharing a node with any of
      /// those (the nodal normals and sizes sum over them); and the
      /// interface DoFs of their nodes. The master-side forces of its
      /// segments are to go to the master DoFs' owners as values, so not
      /// the slave faces coupled to its own master faces. At the last
      /// search (faces_within_reach() finds them without the gathered
      /// surface); every rank still holds every face.
      unsigned int faces_within_reach = 0, dofs_within_reach = 0;
      /// Bytes of the interface's per-face and per-node data (faces,
      /// nodes, slave nodes with their M, the interface DoFs and their
      /// positions), estimated from the containers' sizes; the
      /// formulation's per-node state (a few doubles per node) and
      /// linearised_nodes are not counted.
      double bytes = 0.;
    };

    HeldCounts
    count_held() const;

    /**
     * Search and mortar integration on X + u, @p u given at dofs(). The box
     * of a slave face of pair p is enlarged by @p search_factor times its
     * length plus @p motion_allowance[p] (empty: none), the relative motion
     * of the surfaces the operators must reach.
     */
    void
    update(const std::vector<double> &u,
           const double               search_factor,
           const std::vector<double> &motion_allowance = {});

    /// linearised_nodes of the paired slave nodes whose x DoF this rank
    /// owns (the rows it assembles), at the configuration of the last
    /// update() (contact_interface_linearisation.cc); with the quantities
    /// of the frictional conditions if @p frictional. Only the slave faces
    /// at those nodes are linearised. Not collective.
    void
    linearise(const bool frictional);

    /// Per pair: a bound of how far the slave surface moved relative to the
    /// master from @p from to @p to (both at dofs()): the largest slave plus
    /// the largest master displacement change. Collective (over the faces
    /// of each rank, then an MPI max).
    std::vector<double>
    relative_motion(const std::vector<double> &from, const std::vector<double> &to) const;

    /// The interface displacement the last search was made on.
    const std::vector<double> &
    search_configuration() const
    {
      return search_displacement;
    }

    /// relative_motion() since the configuration of the last search.
    std::vector<double>
    motion_since_search(const std::vector<double> &u) const
    {
      return relative_motion(search_displacement, u);
    }

    /// Per pair: the motion the last search is sure to cover (its allowance
    /// plus the search factor times the smallest slave face).
    const std::vector<double> &
    search_reach() const
    {
      return reach_of_search;
    }

    /**
     * Independent check of the contact: the signed distance of the nodes
     * @p points[i], i in @p which, (slave_nodes or hanging_slave_vertices)
     * at X + u to the whole master surface of its pair, on the true face
     * geometry, by an R-tree of the master faces and the closest point;
     * negative when the node is inside the master body. +infinity where the
     * closest point lies beyond the rim of the master surface. Does not use
     * the mortar operators. Not collective: a rank asks for the nodes it
     * owns (SearchControl::check_penetration()).
     */
    std::vector<double>
    surface_distances(const std::vector<SlaveNode>    &points,
                      const std::vector<unsigned int> &which,
                      const std::vector<double>       &u) const;

    /// surface_distances() of every node of @p points.
    std::vector<double>
    surface_distances(const std::vector<SlaveNode> &points, const std::vector<double> &u) const;

    /**
     * The gap the mortar operators predict at the node itself: the nodal
     * form n_j . (sum_l M_jl x_l - D_j x_j) / D_j, which differs from gap()
     * by the curvature gap (the weighted mean along a curved face). Only
     * for paired nodes.
     */
    double
    nodal_gap(const SlaveNode &s, const std::vector<double> &u) const;

    /// How far a paired slave node moved relative to the master point it is
    /// paired with (the M-weighted master displacement) since the search.
    double
    slip_since_search(const SlaveNode &s, const std::vector<double> &u) const;

    /// Displacement of node @p n from values at dofs().
    Tensor<1, dim>
    displacement(const unsigned int n, const std::vector<double> &u) const;

    /// E* = 1 / ((1 - nu_s^2) / E_s + (1 - nu_m^2) / E_m) of the two sides of
    /// pair @p pair (the materials of the pair's faces; each side one body):
    /// the modulus of Hertz' theory. Found at initialize() from the faces
    /// of every rank; not collective.
    double
    contact_modulus(const unsigned int pair = 0) const;

    /// The largest Young's modulus of the slave (@p slave) or master faces of
    /// pair @p pair (0 without faces); not collective.
    double
    largest_youngs_modulus(const unsigned int pair, const bool slave) const
    {
      return pair_materials.at(pair).largest_youngs_modulus[slave];
    }

    /// The trace of a slave face on its owners (its regular nodes and the
    /// parents of its hanging vertices, in the order of its nodes): T(q, a)
    /// is the weight of owner q in node a.
    struct FaceTrace
    {
      std::vector<unsigned int> owners;
      FullMatrix<double>        T;
    };

    /// The trace of slave face @p f; no owners if it has no hanging vertex.
    FaceTrace
    face_trace(const unsigned int f) const;

    /// Whether a face of @p trace whose nodes have the dual weights @p D
    /// (summed over its masters) gets dual functions of its owners
    /// (add_constrained_face()): its owners form a basis of its trace and
    /// no D is negligible. Otherwise its hanging rows are lumped.
    static bool
    has_owner_duals(const FaceTrace &trace, const std::vector<double> &D);

    /// The geometry of @p face at X + u (@p u per interface node; empty:
    /// the reference configuration). Its geometry points move with the
    /// (bi)linear interpolation of the vertex displacements.
    FaceGeometry
    face_geometry(const Face &face, const std::vector<Tensor<1, dim>> &u = {}) const;

    /**
     * Normalised weighted gap g_j = (n_j . (sum_l M_jl x_l - D_j x_j) +
     * curvature_gap_j) / D_j of a slave node at x = X + u (u at dofs()),
     * positive when apart. The operators are those of the last update().
     */
    double
    gap(const SlaveNode &s, const std::vector<double> &u) const;

    /// A slave node is paired when the master covers more than this part of
    /// its support (D_j > fraction x full_area): tiny or negative dual
    /// weights at the rim of the master surface leave its gap ill-defined.
    static constexpr double least_covered_fraction = 1e-2;

    std::vector<ContactPair> pairs;
    std::vector<Node>        nodes;
    std::vector<Face>        faces;
    std::vector<SlaveNode>   slave_nodes;
    /// Per node of the slave and of the master surfaces at the last
    /// search: its mean unit normal and plane-strain modulus, the
    /// ingredients of SlaveNode::interface_normal (linearise()).
    std::map<unsigned int, std::pair<Tensor<1, dim>, double>> slave_surface_normals,
      master_surface_normals;
    /// Per paired slave node (by node index) whose x DoF this rank owns,
    /// after linearise().
    std::map<unsigned int, LinearisedNode> linearised_nodes;
    /// The hanging vertices of the slave surfaces at the last search (3D
    /// adaptive meshes): no multiplier, but checked against penetration like
    /// the slave nodes. Only node, pair, normal and size are set; paired
    /// when one of their parents is.
    std::vector<SlaveNode>      hanging_slave_vertices;
    std::vector<PairStatistics> statistics;
    /// The slave and master faces (indices in faces) the last search found
    /// a mortar segment between, as (slave face, master face).
    std::vector<std::pair<unsigned int, unsigned int>> coupled_faces;
    /// Length of every face (in 3D the side of a square of its area) at
    /// the configuration of the last search.
    std::vector<double> face_lengths;
    unsigned int        degree          = 1; ///< of the elements
    unsigned int        geometry_degree = 1; ///< of the face geometry
    /// How the surfaces are split over the ranks (locally owned faces).
    std::vector<unsigned int> slave_faces_per_rank, master_faces_per_rank;
    /// The faces (indices in faces) this rank contributed at set-up, the
    /// slave faces among them the ones whose broad phase it runs:
    /// [first, second).
    std::pair<unsigned int, unsigned int> own_faces = {0, 0};

    /// Whether this rank owns node @p n: a node belongs to the rank of the
    /// first face (in face order) holding it, so every node has one owner.
    bool
    owns_node(const unsigned int n) const
    {
      return own_nodes[n];
    }

  private:
    /// Sets own_nodes and slave_node_counts: each rank counts the nodes
    /// whose first face (in face order) is its own, the counts are summed.
    void
    count_own_slave_nodes();

    /// Sets the row holders of the regular slave nodes (owned_row_nodes,
    /// ghost_row_nodes, row_holder) from the locally relevant DoFs
    /// @p relevant, and empties the imports of share_node_values().
    void
    find_row_holders(const IndexSet &relevant);

    /// Sets state_held from slave_nodes' M and relevant_dofs (at each
    /// search): holds_state().
    void
    close_ghosts();

    /// Sets line_held and held_line_dofs from relevant_dofs, the DoFs of
    /// linearised_nodes and slave_nodes' M (at each search and by
    /// linearise()): holds_line().
    void
    close_lines();

    /// Sets Node::symmetry_plane from the boundary faces of the locally
    /// owned cells of @p dof_handler (at the reference configuration) and
    /// the Dirichlet constraints @p dirichlet, gathered over the ranks; the
    /// faces of @p moving_supports are left out.
    void
    find_symmetry_planes(const DoFHandler<dim>              &dof_handler,
                         const AffineConstraints<double>    &dirichlet,
                         const std::set<types::boundary_id> &moving_supports);

    /// Sets pair_materials from the faces of every rank.
    void
    find_pair_materials();

    /// The length of one face record packed by initialize(): pair, slave,
    /// E, nu, orientation, per node its coordinates, DoFs and fixed flags,
    /// then the geometry points.
    static unsigned int
    face_record_size(const unsigned int nodes_per_face, const unsigned int n_geometry_points)
    {
      return 5 + nodes_per_face * 3 * dim + n_geometry_points * dim;
    }

    /// The check of number_own_faces() (checking_held_state()): the numbers
    /// of this rank's faces (@p packed, as initialize() packs them) and of
    /// their nodes computed from them alone must be those unpack_faces()
    /// gave; stops every rank otherwise. Collective.
    void
    check_own_numbering(const std::vector<double> &packed,
                        const unsigned int         nodes_per_face,
                        const unsigned int         n_geometry_points) const;

    /// The check of faces_within_reach() (checking_held_state()): the faces
    /// it finds from this rank's own faces by exchanging boxes must be those
    /// update() marked within reach on the gathered surface (@p geometries,
    /// the search's @p search_factor and @p motion_allowance), with their
    /// nodes and records; stops every rank otherwise. Collective.
    /// checking_held_surface(): NaN in the numbers of the slave nodes off
    /// the faces within reach.
    void
    poison_nodes_beyond_reach();

    void
    check_faces_within_reach(const std::vector<FaceGeometry> &geometries,
                             const double                     search_factor,
                             const std::vector<double>       &motion_allowance) const;

    /// The record of face @p f as initialize() packs it (face_record_size()),
    /// from the gathered surface.
    std::vector<double>
    face_record(const unsigned int f) const;

    /// Builds nodes and faces from the face records of every rank (@p all,
    /// as packed by initialize()), counting the faces per rank.
    void
    unpack_faces(const std::vector<std::vector<double>> &all,
                 const unsigned int                      nodes_per_face,
                 const unsigned int                      n_geometry_points);

    /// Per surface node: its mean unit normal and mean plane-strain
    /// modulus (surface_node_normals()).
    using SurfaceNormals = std::map<unsigned int, std::pair<Tensor<1, dim>, double>>;

    /// Per node of the slave (@p slave) or master surfaces: the mean unit
    /// normal of its faces and their mean plane-strain modulus E / (1 -
    /// nu^2), weighted by the face @p measures (lengths or areas); with
    /// @p slave_data, also the normal, full_area and size of every slave
    /// node.
    SurfaceNormals
    surface_node_normals(const std::vector<FaceGeometry>   &geometries,
                         const std::vector<double>         &measures,
                         const bool                         slave,
                         std::map<unsigned int, SlaveNode> *slave_data = nullptr) const;

    /**
     * Stops the run if the @p overlaps of slave face @p f with the master
     * faces @p masters leave a hole or a doubled part where the master
     * surface covers the face (away from the rim of the @p facing master
     * faces): a hole in the tiling would shrink the dual weights D_j
     * silently. Specialised per dimension (contact_interface_tiling.cc):
     * the covered intervals of a line face in 2D, the area of the overlap
     * polygons in 3D.
     */
    void
    check_tiling(const unsigned int                            f,
                 const std::vector<FaceGeometry>              &geometries,
                 const std::vector<Tensor<1, dim>>            &normals,
                 const std::vector<unsigned int>              &masters,
                 const typename Mortar::Kernel<dim>::Overlaps &overlaps,
                 const std::vector<unsigned int>              &facing) const;

    /// Adds the operators @p ops of slave face @p f against master face
    /// @p m to the sums of the slave nodes of @p f (D, M, weighted gap) and
    /// records the pair as coupled.
    void
    add_segment(const unsigned int                                      f,
                const unsigned int                                      m,
                const typename Mortar::Kernel<dim>::Operators          &ops,
                std::map<unsigned int, SlaveNode>                      &slave_data,
                std::map<unsigned int, std::map<unsigned int, double>> &M_of_node,
                std::map<unsigned int, Tensor<1, dim>>                 &weighted_gap_of_node);

    /// Reads the parents of the hanging vertices of the surfaces from
    /// @p hanging (their x components; the hanging-node weights are the same
    /// for every component), gathered from all ranks.
    void
    find_hanging_vertices(const AffineConstraints<double> &hanging);

    /// Moves the M columns of hanging master vertices to their parents with
    /// the hanging-node weights, and what is left on a hanging slave vertex
    /// (its full area; D, M and weighted gap of faces that
    /// add_constrained_face() could not take, lumped) to its parents.
    void
    condense_hanging_vertices(std::map<unsigned int, SlaveNode>                      &slave_data,
                              std::map<unsigned int, std::map<unsigned int, double>> &M_of_node,
                              std::map<unsigned int, Tensor<1, dim>> &weighted_gap_of_node) const;

    /**
     * Adds the @p segments (master face, operators) of slave face @p f in
     * the dual basis of the constrained trace, if @p f has hanging
     * vertices: D, M and the weighted gap go to the owners of the face (its
     * regular nodes and the parents of its hanging vertices) with dual
     * functions biorthogonal to the owners' trace functions on @p f, so the
     * mortar D stays diagonal and exact for every displacement of the
     * constrained space. Returns false (nothing added) for a face without
     * hanging vertices, or one whose owners do not form a basis of its
     * trace (then its hanging rows are lumped onto the parents).
     */
    bool
    add_constrained_face(
      const unsigned int                                                                   f,
      const std::vector<std::pair<unsigned int, typename Mortar::Kernel<dim>::Operators>> &segments,
      std::map<unsigned int, SlaveNode>                      &slave_data,
      std::map<unsigned int, std::map<unsigned int, double>> &M_of_node,
      std::map<unsigned int, Tensor<1, dim>>                 &weighted_gap_of_node);

    /// Fills slave_nodes from the integrated operators: a node is paired
    /// when the master covers a fair part of its support; its M entries,
    /// curvature gap and interface normal (the slave normal against the
    /// M-weighted master normal, weighted by the moduli) are set. 2D and 3D.
    void
    store_slave_nodes(std::map<unsigned int, SlaveNode>                      &slave_data,
                      std::map<unsigned int, std::map<unsigned int, double>> &M_of_node,
                      std::map<unsigned int, Tensor<1, dim>>                 &weighted_gap_of_node,
                      const std::vector<double>                              &u_at_dofs,
                      const SurfaceNormals                                   &slave_normals,
                      const SurfaceNormals                                   &master_normals);

    /// The mortar segments of a slave face: (master face, operators).
    using Segments = std::vector<std::pair<unsigned int, typename Mortar::Kernel<dim>::Operators>>;

    /**
     * Search and integration of pair @p p on the face @p geometries of
     * @p measures: adds D, M and the weighted gap of the slave nodes of the
     * pair, and sets its statistics. Each rank runs the broad phase of its
     * own slave faces; the faces with candidate masters are shared out
     * over the ranks by their number of candidates, each rank computes the
     * narrow phase and the integration of its share (integrate_faces());
     * the segments are then exchanged and every rank adds all of them in
     * face order, so the sums are those of a serial run, bit for bit.
     */
    void
    search_pair(const unsigned int                                      p,
                const std::vector<FaceGeometry>                        &geometries,
                const std::vector<double>                              &measures,
                const double                                            search_factor,
                const double                                            allowance,
                std::map<unsigned int, SlaveNode>                      &slave_data,
                std::map<unsigned int, std::map<unsigned int, double>> &M_of_node,
                std::map<unsigned int, Tensor<1, dim>>                 &weighted_gap_of_node);

    /// The narrow phase and the integration of the slave faces @p share
    /// against the master faces in @p tree whose boxes meet the face's box
    /// enlarged by @p reach (per face), packed for unpack_segments(): per
    /// face with segments, its index, their number, and per segment the
    /// master face, D, M and the weighted gap. A failed tiling check ends
    /// the loop with its message in @p error.
    template <class Tree>
    std::vector<double>
    integrate_faces(const std::vector<unsigned int>         &share,
                    const std::vector<FaceGeometry>         &geometries,
                    const Tree                              &tree,
                    const std::vector<double>               &reach,
                    const std::map<unsigned int, SlaveNode> &slave_data,
                    std::string                             &error) const;

    /**
     * Collective: the statistics of a pair from its segments
     * @p segments_of_face, of which this rank weighs those of its @p share
     * (the slave faces it integrated) and gathers the weights of the
     * others: sums in face order, bit for bit those of one rank.
     */
    PairStatistics
    statistics_of_segments(const std::vector<unsigned int>        &share,
                           const std::map<unsigned int, Segments> &segments_of_face,
                           const std::vector<double>              &measures,
                           const double                            search_factor) const;

    /// Collective: if @p error (this rank's) or that of another rank is not
    /// empty, every rank throws the first of them (by rank), so a check
    /// that fails on one rank stops all of them instead of leaving the
    /// others waiting in the next collective call.
    void
    stop_on_every_rank(const std::string &error) const;

    /// The segments of every face in @p packed (integrate_faces() of
    /// all ranks, in rank order), by slave face.
    std::map<unsigned int, Segments>
    unpack_segments(const std::vector<std::vector<double>> &packed) const;

    /// Per pair, of its master (0) and slave (1) faces: E and nu of the
    /// last face (each side one body), the largest E.
    struct PairMaterials
    {
      std::array<double, 2> youngs_modulus = {{0., 0.}}, poisson_ratio = {{0., 0.}},
                            largest_youngs_modulus = {{0., 0.}};
    };
    std::vector<PairMaterials>            pair_materials;
    std::pair<unsigned int, unsigned int> slave_node_counts = {0, 0};
    std::vector<bool>                     own_nodes; ///< owns_node(), per node
    /// Displacement at dofs() of the last search, and its reach per pair.
    std::vector<double>                             search_displacement;
    std::vector<double>                             reach_of_search;
    /// Per face, whether it is within reach of this rank's slave faces at
    /// the last search (HeldCounts::faces_within_reach).
    std::vector<char>                               within_reach;
    /// checking_held_surface(): per node, whether this rank will hold it.
    std::vector<char>                               node_within_reach;
    std::vector<types::global_dof_index>            interface_dofs;
    std::map<types::global_dof_index, unsigned int> dof_position;
    std::vector<bool>                               fixed_positions; ///< by position in dofs()
    IndexSet                                        owned_dofs;
    /// The DoFs of dofs() this rank owns, the others (its ghosts), and the
    /// import of the ghosts' values from their owners (gather()); shared
    /// by copies of the interface, since it does not change until the next
    /// initialize().
    IndexSet owned_interface_dofs, ghost_interface_dofs;
    std::shared_ptr<const Utilities::MPI::NoncontiguousPartitioner> ghost_import;
    /// The rank owning each DoF of dofs() (sum_forces()).
    std::vector<unsigned int> owner_of_position;
    /// The regular slave nodes whose row this rank owns and its ghosts,
    /// each sorted by x DoF (the order of the import); per node 1 if its
    /// row is owned here, 2 if a ghost, 0 otherwise (and for other nodes).
    std::vector<unsigned int> owned_row_nodes, ghost_row_nodes;
    std::vector<char>         row_holder;
    /// The imports of share_node_values(), per number of fields, built at
    /// the first call (collective, as the call is); shared by copies.
    std::shared_ptr<
      std::map<unsigned int, std::shared_ptr<const Utilities::MPI::NoncontiguousPartitioner>>>
      row_imports;
    /// HeldCounts::zone_nodes_received, shared by copies.
    std::shared_ptr<unsigned int> zone_nodes_received;
    /// The locally relevant DoFs (initialize()) and, per node, whether its
    /// state is held here (holds_state()).
    IndexSet          relevant_dofs;
    std::vector<char> state_held;
    /// HeldCounts::check_dofs_compared and check_dofs_left_out, shared by
    /// copies.
    std::shared_ptr<std::pair<unsigned int, unsigned int>> held_check_counts;
    /// Per node, whether its lines are held here (holds_line()), and
    /// line_dofs().
    std::vector<char> line_held;
    IndexSet          held_line_dofs;
    /// HeldCounts::check_lines_compared and check_lines_left_out, shared by
    /// copies.
    std::shared_ptr<std::pair<unsigned int, unsigned int>> line_check_counts;
    MPI_Comm                                               mpi_communicator;
  };

  /// The number of @p dofs whose constraint lines in @p held and @p full
  /// differ: constrained in one only, or other entries, order or
  /// inhomogeneity, bit for bit (a DoF a constraint object cannot store
  /// counts as unconstrained there); summed over @p comm (collective). The
  /// checks of the held lines (ContactInterface::check_held_lines()).
  unsigned int
  count_differing_lines(const AffineConstraints<double>            &held,
                        const AffineConstraints<double>            &full,
                        const std::vector<types::global_dof_index> &dofs,
                        const MPI_Comm                              comm);

  // The tiling checks differ by dimension (contact_interface_tiling.cc).
  template <>
  void
  ContactInterface<2>::check_tiling(const unsigned int,
                                    const std::vector<Mortar::LineFace> &,
                                    const std::vector<Tensor<1, 2>> &,
                                    const std::vector<unsigned int> &,
                                    const Mortar::Kernel<2>::Overlaps &,
                                    const std::vector<unsigned int> &) const;
  template <>
  void
  ContactInterface<3>::check_tiling(const unsigned int,
                                    const std::vector<Mortar::QuadFace> &,
                                    const std::vector<Tensor<1, 3>> &,
                                    const std::vector<unsigned int> &,
                                    const Mortar::Kernel<3>::Overlaps &,
                                    const std::vector<unsigned int> &) const;
} // namespace contact_fem

#endif
