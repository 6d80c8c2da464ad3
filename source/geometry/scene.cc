#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <contact_fem/core/format.h>
#include <contact_fem/core/parameters.h>
#include <contact_fem/geometry/physical_names.h>
#include <contact_fem/geometry/scene.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    /// Per built-in geometry, the values of builtin_scene_keys() in that
    /// order: the Hertz demo (prm/hertz.prm), Kratos' 3D Hertz example
    /// (prm/hertz_3d.prm) and the patch test of the blocks (exact pressure 2).
    const std::vector<std::pair<std::string, std::vector<std::string>>> &
    builtin_table()
    {
      static const std::vector<std::pair<std::string, std::vector<std::string>>> table = {
        {"hertz cylinder", {"2: xy; 1: x", "1: 0.2*t", "3: 4", "1, 2", "200, 2e12", "0.3, 0.3"}},
        {"hertz sphere",
         {"2: xyz; 5: x; 6: y", "1: 5e5 * t", "3: 4", "1, 2", "1e8, 1e12", "0.29, 0.29"}},
        {"contact blocks", {"2: y; 5: x; 6: x", "1: 2", "3: 4", "1, 2", "100, 200", "0.3, 0.3"}}};
      return table;
    }
  } // namespace

  std::vector<std::pair<std::string, bool>>
  builtin_scene_keys()
  {
    return {{"Boundary conditions/Fixed", false},
            {"Boundary conditions/Pressure", false},
            {"Contact/Pairs", true},
            {"Materials/Material ids", true},
            {"Materials/Young's moduli", true},
            {"Materials/Poisson's ratios", true}};
  }

  std::vector<BuiltinSetting>
  builtin_scene_settings(const std::string &type)
  {
    std::vector<BuiltinSetting> settings;
    const auto                  keys = builtin_scene_keys();
    for (const auto &[name, values] : builtin_table())
      if (name == type)
        for (unsigned int k = 0; k < keys.size(); ++k)
          settings.push_back({keys[k].first, values[k]});
    return settings;
  }

  std::string
  builtin_scene_help()
  {
    const auto  keys = builtin_scene_keys();
    std::string text = " The built-in scenes give the keys that the input does not set "
                       "their own values:";
    for (const auto &[name, values] : builtin_table())
      {
        text += " " + name + ":";
        for (unsigned int k = 0; k < keys.size(); ++k)
          text += std::string(k == 0 ? " " : ", ") + keys[k].first + " = '" + values[k] + "'";
        text += ";";
      }
    return text + " a mesh file gets none of them (Contact/Pairs and the Materials are "
                  "then required).";
  }

  template <int dim>
  void
  Scene<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry("Type", "hertz cylinder",
                      Patterns::Selection("hertz cylinder|hertz sphere|contact blocks|mesh file"),
                      "The mesh: 'hertz cylinder' (half-disc on a plate, built in "
                      "code and graded toward the contact zone; 2D), 'hertz "
                      "sphere' (a quarter of a hemisphere on a quarter plate, "
                      "with the symmetry planes x = 0 and y = 0, or a half: Hertz "
                      "sphere/Model; 3D), 'contact blocks' "
                      "(two stacked blocks with non-matching meshes), or 'mesh "
                      "file' (a Gmsh .msh file named by 'Mesh file')." +
                        builtin_scene_help());
    prm.declare_entry("Mesh file", "", Patterns::Anything(),
                      "Gmsh file (ASCII, format 2.2 or 4) for Type = mesh file; a "
                      "relative name is taken relative to the .prm file. Bodies "
                      "are the cells' physical tags (material ids), surfaces the "
                      "faces' physical tags (boundary ids); their physical names "
                      "(Gmsh $PhysicalNames) may stand for the ids in every key "
                      "that takes one. A mesh far from the origin (more than 10 "
                      "times its size) is computed moved next to it; the input "
                      "stays in the file's coordinates. Cells: first-order "
                      "quadrilaterals and triangles (2D), hexahedra, tetrahedra "
                      "and prisms (3D); a mesh with triangles, tetrahedra or "
                      "prisms is split on reading, every cell into "
                      "quadrilaterals or hexahedra at its corners (README, "
                      "Meshes). Read and checked with the input (also by "
                      "--validate): binary, truncated, pyramid, second-order "
                      "or wrong-dimension files, degenerate cells and bodies "
                      "cut by unmerged nodes are refused with a message; "
                      "bodies in contact keep their own nodes (different "
                      "material ids).");
    prm.declare_entry("Distortion", "0", Patterns::Double(0., 0.45),
                      "Moves every interior vertex in a random direction by this "
                      "fraction of its shortest adjacent edge (fixed seed, so "
                      "runs repeat exactly); boundary vertices stay. For "
                      "robustness studies on distorted meshes. The Hertz disc "
                      "then has straight interior cell edges (only its arc is "
                      "curved).");
    prm.declare_entry("Global refinements", "0", Patterns::Integer(0, 8),
                      "Uniform refinements applied to the mesh after it is "
                      "built (each one halves every cell).");
    prm.declare_entry("Local refinements", "", Patterns::Anything(),
                      "Boxes refined after the global refinements, as "
                      "'rounds: x_min, y_min, (z_min,) x_max, y_max(, z_max); "
                      "...': 'rounds' times, the cells whose centre lies in the "
                      "box are refined (hanging nodes; neighbours are refined "
                      "as needed to keep one level difference). E.g. "
                      "'2: -1, 0.5, 1, 1.5' refines a band around y = 1 twice. "
                      "Empty: none. Distortion acts before these refinements.");
    prm.declare_entry("Manifolds", "", Patterns::Anything(),
                      "Type = mesh file: the curved surfaces of the mesh, as 'boundary "
                      "id: surface; ...' with the surface 'circle cx, cy, R' in 2D, "
                      "'sphere cx, cy, cz, R' or 'cylinder px, py, pz, dx, dy, dz, R' "
                      "(a point on the axis, its direction, the radius) in 3D, e.g. "
                      "'3: circle 0, 8, 8; 4: circle 0, -8, 8'. Refinement then puts "
                      "the new vertices of these boundaries on their surface instead "
                      "of on the chords of the coarse mesh, the interior of every "
                      "body with such a boundary follows by transfinite "
                      "interpolation (unless Distortion > 0 or the mesh was split "
                      "into quadrilaterals or hexahedra on reading), and Q1 runs on a "
                      "quadratic mapping (Finite element/Mapping degree = auto). "
                      "Every vertex of these boundaries must lie on its surface "
                      "within 1e-4 R. Empty: the faces of the file stay straight, "
                      "and a boundary that looks like a polygon of a curve is "
                      "warned about when the mesh is refined.");
    prm.enter_subsection("Hertz cylinder");
    prm.declare_entry("Radius", "8", Patterns::Double(0.), "Radius R of the half-disc.");
    prm.declare_entry("Plate half width", "10", Patterns::Double(0.),
                      "The plate spans [-w, w] in x.");
    prm.declare_entry("Plate thickness", "1", Patterns::Double(0.),
                      "The plate spans [0, t] in y; the disc touches it at (0, t).");
    prm.declare_entry("Refinement half width", "0.5", Patterns::Double(0.),
                      "Half width of the zone of the plate top toward which the "
                      "mesh is graded; should exceed the expected contact "
                      "half-width.");
    prm.declare_entry("Cylinder refinements", "2", Patterns::Integer(0, 8),
                      "Uniform refinement rounds of the whole disc before the "
                      "graded ones (resolution of the bulk stress field).");
    prm.declare_entry("Grading factor", "4", Patterns::Double(1.),
                      "A cell is refined in a graded round when its distance to "
                      "the contact zone is below this factor times its diameter: "
                      "larger values give a wider, smoother transition.");
    prm.declare_entry("Contact refinements", "6", Patterns::Integer(0, 14),
                      "Number of graded refinement rounds of the disc toward the "
                      "contact zone (each halves the contact elements).");
    prm.declare_entry("Plate contact refinements", "3", Patterns::Integer(0, 14),
                      "Number of graded refinement rounds of the plate.");
    prm.leave_subsection();
    prm.enter_subsection("Hertz sphere");
    prm.declare_entry("Radius", "6.1237", Patterns::Double(0.),
                      "Radius R of the hemisphere (Kratos' 3D Hertz example: "
                      "diameter 12.2474). Its centre is (0, 0, t + g + R), its "
                      "flat face (boundary 1) the plane z = t + g + R (g the "
                      "Initial gap).");
    prm.declare_entry("Initial gap", "0", Patterns::Double(),
                      "Distance g of the hemisphere's lowest point above the "
                      "plate top; negative values make the bodies overlap "
                      "(initial penetration), by less than the Plate thickness. "
                      "A gap leaves the hemisphere free along z until it touches: "
                      "under a pressure the first solve needs nodes that start in "
                      "contact (Contact/Active check factor), so a prescribed "
                      "displacement is the safer load.");
    prm.declare_entry("Plate width", "4", Patterns::Double(0.),
                      "The quarter plate spans [0, w] x [0, w] in x and y; it "
                      "should exceed the expected contact radius.");
    prm.declare_entry(
      "Plate thickness", "1", Patterns::Double(0.),
      "The plate spans [0, t] in z; the hemisphere touches it at "
      "(0, 0, t) (unless Initial gap is set). The plate has about w / t coarse cells per "
      "direction in x and y, one in z.");
    prm.declare_entry("Pole patch angle", "45", Patterns::Double(5., 60.),
                      "Angle in degrees from the lowest point at which the coarse "
                      "patch of the curved surface around it ends (the other "
                      "two patches take the rest of the quarter). 45: three "
                      "patches alike; smaller: finer cells at the contact for "
                      "the same number of cells, coarser ones away from it.");
    prm.declare_entry("Sphere refinements", "3", Patterns::Integer(0, 8),
                      "Uniform refinement rounds of the hemisphere (each halves "
                      "its cells).");
    prm.declare_entry("Plate refinements", "0", Patterns::Integer(0, 8),
                      "Uniform refinement rounds of the plate (a much stiffer, "
                      "flat master needs none: the mortar integrals are exact "
                      "on flat master faces of any size).");
    prm.declare_entry("Contact refinements", "0", Patterns::Integer(0, 14),
                      "Graded refinement rounds of the hemisphere toward the disc "
                      "of radius 'Refinement radius' around the contact point on "
                      "the plate top (as the Hertz cylinder's). They leave "
                      "hanging vertices on the contact surface (the multipliers "
                      "live on the constrained trace).");
    prm.declare_entry("Refinement radius", "2", Patterns::Double(0.),
                      "Radius of the disc on the plate top, around the contact "
                      "point, toward which the graded rounds refine; should "
                      "exceed the expected contact radius.");
    prm.declare_entry("Grading factor", "4", Patterns::Double(1.),
                      "A cell is refined in a graded round when its distance to "
                      "that disc is below this factor times its diameter.");
    prm.declare_entry("Model", "quarter", Patterns::Selection("quarter|half"),
                      "'quarter': the part x, y >= 0, with the symmetry planes "
                      "x = 0 (boundary 5) and y = 0 (boundary 6); 'half': the "
                      "part y >= 0 (the plate spans [-w, w] in x), with the "
                      "symmetry plane y = 0 (boundary 6) only, for loads along x "
                      "(a tangential load: the Cattaneo-Mindlin sphere). The "
                      "built-in Boundary conditions/Fixed names boundary 5: a "
                      "half model sets its own (e.g. '2: xyz; 6: y').");
    prm.leave_subsection();
    prm.enter_subsection("Contact blocks");
    prm.declare_entry("Width", "1", Patterns::Double(0.), "Width W of both blocks.");
    prm.declare_entry("Height", "1", Patterns::Double(0.), "Height H of each block.");
    prm.declare_entry("Initial gap", "0", Patterns::Double(),
                      "Initial distance between the blocks; negative values "
                      "make them overlap (initial penetration).");
    prm.declare_entry("Lower cells", "3", Patterns::Integer(1, 1000),
                      "Cells per direction of the lower (master) block.");
    prm.declare_entry("Upper cells", "5", Patterns::Integer(1, 1000),
                      "Cells per direction of the upper (slave) block.");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  template <int dim>
  void
  Scene<dim>::parse_parameters(ParameterHandler &prm, const std::string &prm_directory)
  {
    prm.enter_subsection("Geometry");
    frame          = ModelFrame<dim>();
    message_origin = {};
    mesh_note.clear();
    facet_note.clear();
    type               = prm.get("Type");
    mesh_file          = prm.get("Mesh file");
    global_refinements = prm.get_integer("Global refinements");
    distortion         = prm.get_double("Distortion");
    refinement_boxes.clear();
    const std::string boxes_key = "Geometry/Local refinements";
    for (const auto &[rounds, box] : split_key_value_list(prm.get("Local refinements"), boxes_key))
      {
        RefinementBox       refinement_box;
        std::vector<double> bounds;
        bool                valid = true;
        try
          {
            std::size_t end       = 0;
            const int   n_rounds  = std::stoi(rounds, &end);
            valid                 = end == rounds.size() && n_rounds >= 1 && n_rounds <= 8;
            refinement_box.rounds = valid ? n_rounds : 0;
            for (const std::string &entry : Utilities::split_string_list(box, ','))
              {
                bounds.push_back(std::stod(entry, &end));
                valid = valid && end == entry.size();
              }
          }
        catch (...)
          {
            valid = false;
          }
        valid = valid && bounds.size() == 2 * dim;
        for (unsigned int d = 0; valid && d < dim; ++d)
          {
            refinement_box.lower[d] = bounds[d];
            refinement_box.upper[d] = bounds[dim + d];
            valid                   = bounds[d] < bounds[dim + d];
          }
        AssertThrow(valid, ExcMessage(boxes_key + ": entry '" + rounds + ": " + box +
                                      "' is not of the form 'rounds: lower corner, upper "
                                      "corner' with rounds in 1..8 and " +
                                      std::to_string(2 * dim) +
                                      " coordinates, each lower below its upper."));
        refinement_boxes.push_back(refinement_box);
      }
    // Parsed once the mesh file is read (its physical names may stand for
    // the boundary ids).
    manifolds.clear();
    AssertThrow(Utilities::trim(prm.get("Manifolds")).empty() || type == "mesh file",
                ExcMessage("Geometry/Manifolds: only for Type = mesh file (the built-in "
                           "geometries attach their own manifolds)."));
    prm.enter_subsection("Hertz cylinder");
    hertz.radius                = prm.get_double("Radius");
    hertz.plate_half_width      = prm.get_double("Plate half width");
    hertz.plate_thickness       = prm.get_double("Plate thickness");
    hertz.refinement_half_width = prm.get_double("Refinement half width");
    hertz.cylinder_refinements  = prm.get_integer("Cylinder refinements");
    hertz.contact_refinements   = prm.get_integer("Contact refinements");
    hertz.grading_factor        = prm.get_double("Grading factor");
    hertz.plate_refinements     = prm.get_integer("Plate contact refinements");
    prm.leave_subsection();
    prm.enter_subsection("Hertz sphere");
    hertz_sphere.radius              = prm.get_double("Radius");
    hertz_sphere.plate_width         = prm.get_double("Plate width");
    hertz_sphere.plate_thickness     = prm.get_double("Plate thickness");
    hertz_sphere.pole_patch_angle    = prm.get_double("Pole patch angle");
    hertz_sphere.sphere_refinements  = prm.get_integer("Sphere refinements");
    hertz_sphere.plate_refinements   = prm.get_integer("Plate refinements");
    hertz_sphere.contact_refinements = prm.get_integer("Contact refinements");
    hertz_sphere.refinement_radius   = prm.get_double("Refinement radius");
    hertz_sphere.grading_factor      = prm.get_double("Grading factor");
    hertz_sphere.gap                 = prm.get_double("Initial gap");
    hertz_sphere.half                = prm.get("Model") == "half";
    prm.leave_subsection();
    prm.enter_subsection("Contact blocks");
    blocks.width       = prm.get_double("Width");
    blocks.height      = prm.get_double("Height");
    blocks.gap         = prm.get_double("Initial gap");
    blocks.lower_cells = prm.get_integer("Lower cells");
    blocks.upper_cells = prm.get_integer("Upper cells");
    prm.leave_subsection();
    prm.leave_subsection();

    const std::pair<const char *, double> lengths[] = {
      {"Hertz cylinder/Radius", hertz.radius},
      {"Hertz cylinder/Plate half width", hertz.plate_half_width},
      {"Hertz cylinder/Plate thickness", hertz.plate_thickness},
      {"Hertz sphere/Radius", hertz_sphere.radius},
      {"Hertz sphere/Plate width", hertz_sphere.plate_width},
      {"Hertz sphere/Plate thickness", hertz_sphere.plate_thickness},
      {"Contact blocks/Width", blocks.width},
      {"Contact blocks/Height", blocks.height}};
    for (const auto &[key, v] : lengths)
      AssertThrow(v > 0., ExcMessage("Geometry/" + std::string(key) + ": got " +
                                     significant(v, 15) + "; expected a length > 0."));
    AssertThrow(std::abs(blocks.gap) < blocks.height,
                ExcMessage("Geometry/Contact blocks/Initial gap: |gap| must be "
                           "smaller than the block height."));
    AssertThrow(hertz_sphere.gap > -hertz_sphere.plate_thickness,
                ExcMessage(
                  "Geometry/Hertz sphere/Initial gap = " + significant(hertz_sphere.gap, 6) +
                  ": an overlap must be smaller than the Plate thickness (" +
                  significant(hertz_sphere.plate_thickness, 6) +
                  "); deeper, the hemisphere would pass through the plate."));

    if (type == "mesh file")
      {
        AssertThrow(!mesh_file.empty(),
                    ExcMessage("Geometry/Mesh file: Type = mesh file needs a file name."));
        if (mesh_file[0] != '/' && !prm_directory.empty())
          mesh_file = prm_directory + "/" + mesh_file;
        std::ifstream in(mesh_file);
        AssertThrow(in.good(), ExcMessage("Geometry/Mesh file: cannot open '" + mesh_file +
                                          "' (no such file, or not readable)."));
        in.seekg(0, std::ios::end);
        AssertThrow(in.tellg() > 0,
                    ExcMessage("Geometry/Mesh file: '" + mesh_file + "' is empty."));
        read_mesh_file(prm);
      }
    else if (type == "hertz sphere")
      {
        AssertThrow(dim == 3, ExcMessage("Geometry/Type: 'hertz sphere' is a 3D geometry (set "
                                         "Dimension = 3; in 2D, 'hertz cylinder')."));
      }
    else
      AssertThrow(dim == 2, ExcMessage("Geometry/Type: the built-in geometry '" + type +
                                       "' exists in 2D only so far; use 'hertz sphere' or a "
                                       "mesh file in 3D."));
  }

  template <int dim>
  void
  Scene<dim>::read_mesh_file(ParameterHandler &prm)
  {
    // Every check runs here, before any work and under --validate.
    const std::string  key    = "Geometry/Manifolds";
    auto               coarse = std::make_shared<Triangulation<dim>>();
    const MeshFileInfo info   = read_gmsh(mesh_file, *coarse);
    PhysicalNames(info.physical_names, dim, mesh_file).substitute(prm);
    prm.enter_subsection("Geometry");
    manifolds = parse_boundary_manifolds<dim>(prm.get("Manifolds"), key);
    prm.leave_subsection();
    for (unsigned int d = 0; d < dim; ++d)
      {
        frame.origin[d]   = info.frame_origin[d];
        message_origin[d] = info.frame_origin[d];
      }
    for (auto &m : manifolds)
      m.centre = frame.to_model(m.centre);
    place_new_vertices_on_manifolds(manifolds, info.first_new_vertex, *coarse);
    mesh_note  = info.split_note;
    facet_note = info.orphan_note;
    check_unmerged_vertices(*coarse, mesh_file);
    check_folded_cells(*coarse, mesh_file, info.frame_origin);
    check_boundary_manifolds(manifolds, *coarse, key);
    set_manifold_ids(manifolds, curved_interior(), *coarse);
    check_refinement_on_manifolds(manifolds, curved_interior(), *coarse, key);
    std::vector<types::boundary_id> with_manifold;
    for (const auto &m : manifolds)
      with_manifold.push_back(m.boundary_id);
    polygonal_boundaries = find_polygonal_boundaries(*coarse, with_manifold);
    coarse_mesh          = coarse;
  }

  template <int dim>
  bool
  Scene<dim>::curved_interior() const
  {
    // Random vertex moves would invalidate the transfinite chart of the
    // coarse cells (as for the Hertz disc): a distorted mesh keeps straight
    // interior lines. So does a split mesh: the corner pieces of
    // tetrahedra touch a curved surface with an edge or a corner only, in
    // great numbers, and the chart's pull-back fails for some of them.
    return distortion == 0. && mesh_note.empty();
  }

  template <int dim>
  void
  Scene<dim>::create_from_mesh_file(parallel::distributed::Triangulation<dim> &tria) const
  {
    AssertThrow(coarse_mesh, ExcMessage("Scene: parse_parameters() reads the mesh file, "
                                        "create_mesh() uses it once."));
    tria.copy_triangulation(*coarse_mesh);
    coarse_mesh.reset();
    attach_manifolds(manifolds, curved_interior(), tria);
  }

  template <int dim>
  std::string
  Scene<dim>::chord_warning() const
  {
    if (polygonal_boundaries.empty())
      return "";
    const bool         one = polygonal_boundaries.size() == 1;
    std::ostringstream ids, details, fitted;
    ids << (one ? "boundary " : "boundaries ");
    details << std::setprecision(2);
    fitted << std::setprecision(8);
    for (unsigned int i = 0; i < polygonal_boundaries.size(); ++i)
      {
        const auto &b = polygonal_boundaries[i];
        ids << (i == 0                               ? "" :
                i + 1 == polygonal_boundaries.size() ? " and " :
                                                       ", ")
            << static_cast<unsigned int>(b.id)
            << (b.id == 0 ? " (the faces without a physical tag)" : "");
        details << (i == 0 ? "" : "; ")
                << (one ? "its faces turn by " :
                          "boundary " + std::to_string(b.id) + ": faces turning by ")
                << b.min_angle * 180. / numbers::PI << " to " << b.max_angle * 180. / numbers::PI
                << " degrees at " << b.n_kinks << " of " << b.n_joints
                << (dim == 2 ? " vertices" : " edges");
        // A cylinder first: the vertices of an extrusion by one layer lie
        // on a sphere too (through its two end circles).
        const auto clean = [](const double x, const double scale) {
          return std::abs(x) < 1e-12 * scale ? 0. : x;
        };
        if (b.fits_cylinder)
          {
            fitted << (fitted.tellp() > 0 ? "; " : "") << static_cast<unsigned int>(b.id)
                   << ": cylinder ";
            for (unsigned int d = 0; d < dim; ++d)
              fitted << clean(frame.to_user(b.axis_point)[d], b.cylinder_radius) << ", ";
            for (unsigned int d = 0; d < dim; ++d)
              fitted << clean(b.axis[d], 1.) << ", ";
            fitted << b.cylinder_radius;
          }
        else if (b.fits_sphere)
          {
            fitted << (fitted.tellp() > 0 ? "; " : "") << static_cast<unsigned int>(b.id)
                   << (dim == 2 ? ": circle " : ": sphere ");
            for (unsigned int d = 0; d < dim; ++d)
              fitted << clean(frame.to_user(b.centre)[d], b.radius) << ", ";
            fitted << b.radius;
          }
      }
    const std::string example =
      fitted.tellp() > 0 ? "'" + fitted.str() + "' (fitted to the vertices)" :
                           (dim == 2 ? "'id: circle cx, cy, R'" :
                                       "'id: sphere cx, cy, cz, R' or 'id: cylinder px, py, pz, "
                                       "dx, dy, dz, R'");
    return ids.str() + " of the mesh file " +
           (one ? "looks like a polygon standing for a curve (" :
                  "look like polygons standing for curves (") +
           details.str() + ") but " + (one ? "has" : "have") +
           " no manifold: refinement keeps the chords of the coarse "
           "mesh (new vertices on the straight edges, a kink and a pressure spike at every "
           "original vertex). Attach the true " +
           (one ? "surface" : "surfaces") + " with Geometry/Manifolds, e.g. " + example + ".";
  }

  namespace
  {
    /// Puts several coarse meshes side by side in one triangulation without
    /// merging coincident vertices: the bodies stay disconnected even where
    /// they touch. The cells of mesh k get material id material_ids[k].
    template <int dim>
    void
    join_bodies(const std::vector<const Triangulation<dim> *> &parts,
                const std::vector<types::material_id>         &material_ids,
                Triangulation<dim>                            &result)
    {
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;
      for (unsigned int k = 0; k < parts.size(); ++k)
        {
          const unsigned int offset = vertices.size();
          vertices.insert(vertices.end(), parts[k]->get_vertices().begin(),
                          parts[k]->get_vertices().end());
          for (const auto &cell : parts[k]->active_cell_iterators())
            {
              CellData<dim> c(GeometryInfo<dim>::vertices_per_cell);
              for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell; ++v)
                c.vertices[v] = cell->vertex_index(v) + offset;
              c.material_id = material_ids[k];
              cells.push_back(c);
            }
        }
      // deal.II wants the lines shared by two cells to be oriented alike.
      GridTools::consistently_order_cells(cells);
      result.create_triangulation(vertices, cells, SubCellData());
    }

    bool
    close(const double a, const double b, const double scale)
    {
      return std::abs(a - b) < 1e-8 * scale;
    }
  } // namespace

  template <>
  void
  Scene<2>::create_hertz_mesh(parallel::distributed::Triangulation<2> &tria) const
  {
    Triangulation<2> coarse;
    const double     R = hertz.radius, t = hertz.plate_thickness;
    const Point<2>   c(0., t + R);
    // Coarse half-disc: a centre cell under the flat top and three cells
    // along the arc; the lowest point of the arc lies inside the bottom
    // cell, so the contact zone is free of coarse vertices.
    const double                s = std::sqrt(0.5);
    const std::vector<Point<2>> v = {c + Point<2>(-R, 0.),
                                     c + Point<2>(R, 0.),
                                     c + Point<2>(-R * s, -R * s),
                                     c + Point<2>(R * s, -R * s),
                                     c + Point<2>(-0.4375 * R, 0.),
                                     c + Point<2>(0.4375 * R, 0.),
                                     c + Point<2>(-0.4375 * R, -0.5 * R),
                                     c + Point<2>(0.4375 * R, -0.5 * R)};
    std::vector<CellData<2>>    cells(4, CellData<2>(4));
    const unsigned int          cell_vertices[4][4] = {{6, 7, 4, 5},
                                                       {2, 3, 6, 7},
                                                       {2, 6, 0, 4},
                                                       {7, 3, 5, 1}};
    for (unsigned int i = 0; i < 4; ++i)
      for (unsigned int j = 0; j < 4; ++j)
        cells[i].vertices[j] = cell_vertices[i][j];
    Triangulation<2> disc;
    GridTools::consistently_order_cells(cells);
    disc.create_triangulation(v, cells, SubCellData());

    Triangulation<2>   plate;
    const unsigned int nx =
      std::max(1, static_cast<int>(std::round(2. * hertz.plate_half_width / t)));
    GridGenerator::subdivided_hyper_rectangle(plate, {nx, 1}, Point<2>(-hertz.plate_half_width, 0.),
                                              Point<2>(hertz.plate_half_width, t));
    join_bodies({&disc, &plate}, {1, 2}, coarse);

    for (const auto &cell : coarse.active_cell_iterators())
      {
        // The transfinite interpolation of the disc interior is charted
        // on the coarse cells: random vertex moves invalidate the chart
        // (its pull-back fails for degree 2), so a distorted disc has
        // straight interior lines and only the arc is curved.
        if (cell->material_id() == 1)
          cell->set_all_manifold_ids(distortion > 0. ? numbers::flat_manifold_id : 2);
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const Point<2> fc = cell->face(f)->center();
              if (cell->material_id() == 1)
                {
                  if (close(fc[1], t + R, R))
                    cell->face(f)->set_boundary_id(1);
                  else
                    {
                      cell->face(f)->set_boundary_id(3);
                      cell->face(f)->set_manifold_id(1);
                    }
                }
              else if (close(fc[1], 0., t))
                cell->face(f)->set_boundary_id(2);
              else if (close(fc[1], t, t))
                cell->face(f)->set_boundary_id(4);
              else
                cell->face(f)->set_boundary_id(0);
            }
      }
    tria.copy_triangulation(coarse);
    tria.set_manifold(1, PolarManifold<2>(c));
    TransfiniteInterpolationManifold<2> tfi;
    if (distortion == 0.)
      {
        tfi.initialize(tria);
        tria.set_manifold(2, tfi);
      }

    // Uniform rounds on the disc only: the plate is nearly rigid in the
    // reference scene and needs no resolution away from the contact.
    for (unsigned int round = 0; round < hertz.cylinder_refinements; ++round)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned() && cell->material_id() == 1)
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
    // Graded rounds toward the segment |x| < w_r of the plate top.
    const unsigned int n_rounds = std::max(hertz.contact_refinements, hertz.plate_refinements);
    for (unsigned int round = 0; round < n_rounds; ++round)
      {
        for (const auto &cell : tria.active_cell_iterators())
          {
            if (!cell->is_locally_owned())
              continue;
            const unsigned int rounds_of_body =
              cell->material_id() == 1 ? hertz.contact_refinements : hertz.plate_refinements;
            if (round >= rounds_of_body)
              continue;
            const Point<2> p        = cell->center();
            const double   dx       = std::max(0., std::abs(p[0]) - hertz.refinement_half_width);
            const double   distance = std::hypot(dx, p[1] - t);
            if (distance < hertz.grading_factor * cell->diameter())
              cell->set_refine_flag();
          }
        tria.execute_coarsening_and_refinement();
      }
  }

  template <>
  void
  Scene<2>::create_contact_blocks(parallel::distributed::Triangulation<2> &tria) const
  {
    Triangulation<2> coarse;
    const double     W = blocks.width, H = blocks.height;
    Triangulation<2> lower, upper;
    GridGenerator::subdivided_hyper_rectangle(lower, {blocks.lower_cells, blocks.lower_cells},
                                              Point<2>(0., 0.), Point<2>(W, H));
    GridGenerator::subdivided_hyper_rectangle(upper, {blocks.upper_cells, blocks.upper_cells},
                                              Point<2>(0., H + blocks.gap),
                                              Point<2>(W, 2. * H + blocks.gap));
    join_bodies({&upper, &lower}, {1, 2}, coarse);
    for (const auto &cell : coarse.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const Point<2>     fc         = cell->face(f)->center();
            const bool         upper_body = cell->material_id() == 1;
            const double       y0         = upper_body ? H + blocks.gap : 0.;
            types::boundary_id id         = 0;
            if (close(fc[1], y0, H))
              id = upper_body ? 3 : 2;
            else if (close(fc[1], y0 + H, H))
              id = upper_body ? 1 : 4;
            else if (close(fc[0], 0., W))
              id = upper_body ? 5 : 6;
            cell->face(f)->set_boundary_id(id);
          }
    tria.copy_triangulation(coarse);
  }

  template <>
  void
  Scene<2>::create_mesh(parallel::distributed::Triangulation<2> &tria) const
  {
    if (type == "mesh file")
      create_from_mesh_file(tria);
    else if (type == "hertz cylinder")
      create_hertz_mesh(tria);
    else if (type == "contact blocks")
      create_contact_blocks(tria);

    if (global_refinements > 0)
      tria.refine_global(global_refinements);
    if (distortion > 0.)
      GridTools::distort_random(distortion, tria, true, 20261121);
    refine_boxes(tria);
  }

  namespace
  {
    /// The coarse mesh of one eighth of the unit ball, the octant x, y >= 0,
    /// z <= 0 (the pole (0, 0, -1) lowest): an inner block at the centre and
    /// one cell under each of the three patches of the curved surface. The
    /// patch around the pole reaches @p pole_patch_angle (radians) from it
    /// along the planes x = 0 and y = 0; pi / 4 makes the three alike.
    /// @p half adds its mirror image about x = 0 (the quarter y >= 0).
    void
    unit_ball_octant(const double pole_patch_angle, const bool half, Triangulation<3> &octant)
    {
      const double s = std::sin(pole_patch_angle), c = std::cos(pole_patch_angle);
      // The surface points: the three poles, the ends of the patch edges on
      // the three arcs, and the corner the three patches share.
      const std::array<Point<3>, 7> directions = {
        {Point<3>(1., 0., 0.), Point<3>(0., 1., 0.), Point<3>(1., 1., 0.), Point<3>(0., 0., -1.),
         Point<3>(s, 0., -c), Point<3>(0., s, -c), Point<3>(s, s, -c)}};
      // Inner block: each surface point pulled in along its direction to
      // the cube of half-width 0.4 (max norm), so the block's faces are
      // planar and the outer cells about as thick (0.6) as they are wide
      // at the pole.
      const double          inner = 0.4;
      std::vector<Point<3>> vertices(1 + 2 * directions.size());
      for (unsigned int k = 0; k < directions.size(); ++k)
        {
          double max_norm = 0.;
          for (unsigned int d = 0; d < 3; ++d)
            max_norm = std::max(max_norm, std::abs(directions[k][d]));
          vertices[1 + k]                     = (inner / max_norm) * directions[k];
          vertices[1 + directions.size() + k] = (1. / directions[k].norm()) * directions[k];
        }
      // Indices: 0 centre; inner 1..7 and outer 8..14 in the order of
      // directions (x pole, y pole, xy arc, lowest pole, xz, yz, shared).
      const unsigned int       cell_vertices[4][8] = {{4, 5, 6, 7, 0, 1, 2, 3},     // block
                                                      {11, 12, 13, 14, 4, 5, 6, 7}, // pole patch
                                                      {5, 12, 7, 14, 1, 8, 3, 10},  // x patch
                                                      {6, 7, 13, 14, 2, 3, 9, 10}}; // y patch
      std::vector<CellData<3>> cells(4, CellData<3>(8));
      for (unsigned int i = 0; i < 4; ++i)
        for (unsigned int v = 0; v < 8; ++v)
          cells[i].vertices[v] = cell_vertices[i][v];
      GridTools::invert_all_negative_measure_cells(vertices, cells);
      if (half)
        {
          // The mirror image x -> -x, with each cell's vertex order
          // mirrored too (positive volume); the vertices on x = 0 (exactly
          // 0 by construction) are shared.
          std::vector<unsigned int> mirror(vertices.size());
          for (unsigned int k = 0; k < mirror.size(); ++k)
            {
              mirror[k] = k;
              if (vertices[k][0] != 0.)
                {
                  mirror[k] = vertices.size();
                  vertices.emplace_back(-vertices[k][0], vertices[k][1], vertices[k][2]);
                }
            }
          for (unsigned int i = 0; i < 4; ++i)
            {
              CellData<3> cell(8);
              for (unsigned int v = 0; v < 8; ++v)
                cell.vertices[v] = mirror[cells[i].vertices[v ^ 1]];
              cells.push_back(cell);
            }
        }
      GridTools::consistently_order_cells(cells);
      octant.create_triangulation(vertices, cells, SubCellData());
    }
  } // namespace

  template <>
  void
  Scene<3>::create_hertz_sphere_mesh(parallel::distributed::Triangulation<3> &tria) const
  {
    const double R = hertz_sphere.radius, t = hertz_sphere.plate_thickness,
                 w = hertz_sphere.plate_width, g = hertz_sphere.gap;
    const Point<3>   centre(0., 0., t + g + R);
    Triangulation<3> sphere;
    unit_ball_octant(hertz_sphere.pole_patch_angle * numbers::PI / 180., hertz_sphere.half, sphere);
    GridTools::transform(
      [&](const Point<3> &p) {
        return Point<3>(centre + R * p);
      },
      sphere);

    Triangulation<3>   plate;
    const unsigned int n = std::max(1, static_cast<int>(std::round(w / t)));
    GridGenerator::subdivided_hyper_rectangle(plate, {hertz_sphere.half ? 2 * n : n, n, 1},
                                              Point<3>(hertz_sphere.half ? -w : 0., 0., 0.),
                                              Point<3>(w, w, t));
    // The pole touches the plate at (0, 0, t) unless lifted by g: joined
    // without merging.
    Triangulation<3> coarse;
    join_bodies({&sphere, &plate}, {1, 2}, coarse);

    // Ids by the plane a face lies in; a face of the hemisphere in none of
    // its planes is on the curved surface.
    for (const auto &cell : coarse.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const auto in_plane = [&](const unsigned int d, const double value) {
              for (unsigned int v = 0; v < 4; ++v)
                if (!close(cell->face(f)->vertex(v)[d], value, std::max(R, w)))
                  return false;
              return true;
            };
            const bool         on_sphere = cell->material_id() == 1;
            types::boundary_id id        = on_sphere ? 3 : 0;
            if (in_plane(0, 0.))
              id = 5;
            else if (in_plane(1, 0.))
              id = 6;
            else if (on_sphere && in_plane(2, t + g + R))
              id = 1;
            else if (!on_sphere && in_plane(2, 0.))
              id = 2;
            else if (!on_sphere && in_plane(2, t))
              id = 4;
            cell->face(f)->set_boundary_id(id);
          }
    // The curved surface on its sphere, the interior by transfinite
    // interpolation (as Geometry/Manifolds does for mesh files).
    BoundaryManifold<3> surface;
    surface.boundary_id = 3;
    surface.kind        = "sphere";
    surface.centre      = centre;
    surface.radius      = R;
    surface.entry       = "Geometry/Type = hertz sphere";
    // Random vertex moves would invalidate the transfinite chart (as for
    // the Hertz disc): a distorted hemisphere has straight interior lines.
    set_manifold_ids<3>({surface}, distortion == 0., coarse);
    tria.copy_triangulation(coarse);
    attach_manifolds<3>({surface}, distortion == 0., tria);

    // Uniform rounds per body, then graded rounds of the hemisphere
    // toward the disc r < "Refinement radius" of the plate top.
    const auto refine = [&](const auto &flag) {
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() && flag(cell))
          cell->set_refine_flag();
      tria.execute_coarsening_and_refinement();
    };
    const unsigned int uniform_rounds =
      std::max(hertz_sphere.sphere_refinements, hertz_sphere.plate_refinements);
    for (unsigned int round = 0; round < uniform_rounds; ++round)
      refine([&](const auto &cell) {
        return round < (cell->material_id() == 1 ? hertz_sphere.sphere_refinements :
                                                   hertz_sphere.plate_refinements);
      });
    for (unsigned int round = 0; round < hertz_sphere.contact_refinements; ++round)
      refine([&](const auto &cell) {
        const Point<3> p  = cell->center();
        const double   dr = std::max(0., std::hypot(p[0], p[1]) - hertz_sphere.refinement_radius);
        return cell->material_id() == 1 &&
               std::hypot(dr, p[2] - t) < hertz_sphere.grading_factor * cell->diameter();
      });
  }

  template <>
  void
  Scene<3>::create_mesh(parallel::distributed::Triangulation<3> &tria) const
  {
    if (type == "hertz sphere")
      create_hertz_sphere_mesh(tria);
    else
      create_from_mesh_file(tria);
    if (global_refinements > 0)
      tria.refine_global(global_refinements);
    if (distortion > 0.)
      GridTools::distort_random(distortion, tria, true, 20261121);
    refine_boxes(tria);
  }

  template <int dim>
  void
  Scene<dim>::refine_boxes(parallel::distributed::Triangulation<dim> &tria) const
  {
    for (unsigned int b = 0; b < refinement_boxes.size(); ++b)
      {
        const RefinementBox &box = refinement_boxes[b];
        for (unsigned int round = 0; round < box.rounds; ++round)
          {
            unsigned int n_marked = 0;
            for (const auto &cell : tria.active_cell_iterators())
              if (cell->is_locally_owned())
                {
                  const Point<dim> centre = frame.to_user(cell->center());
                  bool             inside = true;
                  for (unsigned int d = 0; d < dim; ++d)
                    inside = inside && centre[d] >= box.lower[d] && centre[d] <= box.upper[d];
                  if (inside)
                    {
                      cell->set_refine_flag();
                      ++n_marked;
                    }
                }
            AssertThrow(Utilities::MPI::sum(n_marked, tria.get_communicator()) > 0,
                        ExcMessage("Geometry/Local refinements: box " + std::to_string(b + 1) +
                                   " holds no cell centre (round " + std::to_string(round + 1) +
                                   ")."));
            tria.execute_coarsening_and_refinement();
          }
      }
  }

  template <int dim>
  void
  Scene<dim>::check_mesh(const parallel::distributed::Triangulation<dim> &tria,
                         const std::set<types::material_id>              &material_ids)
  {
    AssertThrow(tria.n_global_active_cells() > 0, ExcMessage("Geometry: the mesh has no cells."));

    // The coarse mesh is known on every rank: its ids are those of the mesh.
    std::set<types::material_id> mesh_materials;
    for (const auto &cell : tria.cell_iterators_on_level(0))
      mesh_materials.insert(cell->material_id());

    for (const auto id : material_ids)
      AssertThrow(mesh_materials.count(id) == 1,
                  ExcMessage("Materials/Material ids: the mesh has no cells with "
                             "material id " +
                             std::to_string(id) + "."));
    for (const auto id : mesh_materials)
      AssertThrow(material_ids.count(id) == 1,
                  ExcMessage("Materials/Material ids: the mesh has cells with material id " +
                             std::to_string(id) + ", which has no material constants."));

    // Inverted or degenerate cells: the corner Jacobians of a valid cell are
    // all positive.
    unsigned int bad_cells = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() && is_inverted<dim>(cell))
        ++bad_cells;
    bad_cells = Utilities::MPI::sum(bad_cells, tria.get_communicator());
    AssertThrow(bad_cells == 0,
                ExcMessage("Geometry: the mesh has " + std::to_string(bad_cells) +
                           " inverted or degenerate cells (non-positive Jacobian at "
                           "a corner)."));
  }

  template class Scene<2>;
  template class Scene<3>;
} // namespace contact_fem
