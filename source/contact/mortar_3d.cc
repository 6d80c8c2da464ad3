#include <deal.II/base/quadrature_lib.h>
#include <deal.II/differentiation/ad.h>

#include <contact_fem/contact/mortar.h>
#include <contact_fem/core/format.h>
#include <contact_fem/contact/mortar_3d.h>
#include <contact_fem/contact/mortar_3d_number.h>
#include <contact_fem/contact/mortar_kernel.h>
#include <contact_fem/contact/mortar_number.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace contact_fem
{
  namespace Mortar
  {
    namespace
    {
      /// Boundary nodes of a face of geometry degree @p p, counterclockwise
      /// in the parameter plane.
      std::vector<unsigned int>
      boundary_ring(const unsigned int p)
      {
        if (p == 1)
          return {0, 1, 3, 2};
        return {0, 6, 1, 5, 3, 7, 2, 4};
      }

      template <typename Number>
      Number
      cross_2d(const Tensor<1, 2, Number> &a, const Tensor<1, 2, Number> &b)
      {
        return a[0] * b[1] - a[1] * b[0];
      }

      double
      clamp(const double x)
      {
        return std::max(-1., std::min(1., x));
      }

      /// The values of a point or vector of double or AD numbers.
      template <int dim, typename Number>
      Point<dim>
      point_value(const Tensor<1, dim, Number> &x)
      {
        Point<dim> v;
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = value_of(x[d]);
        return v;
      }
      template <typename Number>
      Tensor<1, 3>
      vector_value(const Tensor<1, 3, Number> &x)
      {
        if constexpr (std::is_same_v<Number, double>)
          return x;
        else
          return point_value(x);
      }

      template <typename Number>
      Number
      abs_of(const Number &x)
      {
        if constexpr (std::is_same_v<Number, double>)
          return std::abs(x);
        else
          return x.val() < 0. ? Number(-x) : x;
      }

      /// The parameter @p xi clamped to the face as clamp(); a clamped AD
      /// coordinate is constant (one-sided derivative at the face's rim).
      template <typename Number>
      Point<2, Number>
      clamped(const Point<2, Number> &xi)
      {
        if constexpr (std::is_same_v<Number, double>)
          return Point<2>(clamp(xi[0]), clamp(xi[1]));
        else
          {
            Point<2, Number> result = xi;
            for (unsigned int d = 0; d < 2; ++d)
              if (std::abs(xi[d].val()) > 1.)
                result[d] = Number(clamp(xi[d].val()));
            return result;
          }
      }

      /// A polygon in the auxiliary plane: (e1, e2) coordinates, not closed.
      using PlanePolygon = std::vector<Point<2>>;

      /// Twice the signed area (positive: counterclockwise).
      template <typename Number>
      Number
      twice_signed_area(const std::vector<Point<2, Number>> &polygon)
      {
        Number area = 0.;
        for (unsigned int k = 0; k < polygon.size(); ++k)
          area += cross_2d(polygon[k], polygon[(k + 1) % polygon.size()]);
        return area;
      }

      /// Whether the counterclockwise @p polygon turns left or goes straight
      /// on at every vertex, up to a turn of 1e-10 rad (collinear edge
      /// midpoints stay convex).
      bool
      is_convex(const PlanePolygon &polygon)
      {
        const unsigned int m = polygon.size();
        for (unsigned int k = 0; k < m; ++k)
          {
            const Tensor<1, 2> a = polygon[(k + 1) % m] - polygon[k];
            const Tensor<1, 2> b = polygon[(k + 2) % m] - polygon[(k + 1) % m];
            if (cross_2d(a, b) < -1e-10 * a.norm() * b.norm())
              return false;
          }
        return true;
      }

      /**
       * The counterclockwise @p ring as convex pieces: itself if convex,
       * otherwise the fan from @p centre (a point from which the ring is
       * star-shaped: the projected face centre) with consecutive triangles
       * merged while they stay convex - e.g. two pieces for a face whose
       * projected edge bends inward at its midpoint (a face bounded by a
       * parallel of a sphere, seen from above). Empty if the ring is not
       * star-shaped from @p centre (a face folded over in the projection).
       */
      std::vector<PlanePolygon>
      convex_pieces(const PlanePolygon &ring, const Point<2> &centre)
      {
        if (is_convex(ring))
          return {ring};
        const unsigned int m = ring.size();
        for (unsigned int k = 0; k < m; ++k)
          if (!(cross_2d(ring[k] - centre, ring[(k + 1) % m] - centre) > 0.))
            return {};
        // Start at a reflex vertex: no convex piece passes through one.
        unsigned int start = 0;
        for (unsigned int k = 0; k < m; ++k)
          {
            const Tensor<1, 2> a = ring[(k + 1) % m] - ring[k];
            const Tensor<1, 2> b = ring[(k + 2) % m] - ring[(k + 1) % m];
            if (cross_2d(a, b) < -1e-10 * a.norm() * b.norm())
              start = (k + 1) % m;
          }
        std::vector<PlanePolygon> pieces;
        PlanePolygon              piece = {centre, ring[start]};
        for (unsigned int i = 1; i <= m; ++i)
          {
            const Point<2> next = ring[(start + i) % m];
            piece.push_back(next);
            if (piece.size() > 3 && !is_convex(piece))
              {
                piece.pop_back();
                pieces.push_back(piece);
                piece = {centre, piece.back(), next};
              }
          }
        pieces.push_back(piece);
        return pieces;
      }

      /**
       * The fraction sp / (sp - sq) of the way from p to q where the segment
       * pq crosses the line of a clip @p edge (sp, sq: the cross products of
       * @p edge with p and q from its start). Where pq runs along the edge up
       * to round-off (rims of faces that coincide), the crossing is anywhere
       * on it and its derivative is round-off over round-off (1e16 and more,
       * times a sliver width that the fan integration does not cancel in
       * floating point): there the fraction is held, and the vertex moves with
       * p and q, a bounded one-sided derivative of the overlap.
       */
      template <typename Number>
      Number
      crossing_fraction(const Number               &sp,
                        const Number               &sq,
                        const Tensor<1, 2, Number> &edge,
                        const Tensor<1, 2, Number> &pq)
      {
        const Number fraction = sp / (sp - sq);
        if constexpr (std::is_same_v<Number, double>)
          return fraction;
        else
          {
            // |sp - sq| = |edge| |pq| sin(angle between them).
            const double sine =
              std::abs(value_of(sp - sq)) / (value_of(edge.norm()) * value_of(pq.norm()));
            return sine > 1e-10 ? fraction : Number(value_of(fraction));
          }
      }

      /**
       * Sutherland-Hodgman: @p subject (any simple polygon) clipped by the
       * half-planes of the edges of the convex, counterclockwise @p clip.
       * Where the intersection falls apart into several parts, they come as
       * one polygon joined by edges of zero width along the clip edges, run
       * through once each way: the same area, and the fan integration of
       * for_each_point() cancels them exactly. Each step is a continuous
       * function of the input, so edges that coincide up to round-off
       * (faces that touch along an edge, or share one) give a sliver of
       * round-off width or nothing, never a wrong region. (boost.geometry's
       * overlay, used before, returned the whole slave for some such pairs:
       * on the two cylinders extruded and refined, whose faces meet edge on
       * edge at 1e-14 after the transfinite interpolation of the interior.)
       */
      template <typename Number>
      std::vector<Point<2, Number>>
      clip_convex(const std::vector<Point<2, Number>> &subject,
                  const std::vector<Point<2, Number>> &clip)
      {
        std::vector<Point<2, Number>> result = subject, input;
        for (unsigned int e = 0; e < clip.size() && !result.empty(); ++e)
          {
            const Point<2, Number>     a    = clip[e];
            const Tensor<1, 2, Number> edge = clip[(e + 1) % clip.size()] - a;
            input.swap(result);
            result.clear();
            for (unsigned int k = 0; k < input.size(); ++k)
              {
                const Point<2, Number> &p = input[k], &q = input[(k + 1) % input.size()];
                const Number            sp = cross_2d(edge, Tensor<1, 2, Number>(p - a)),
                             sq            = cross_2d(edge, Tensor<1, 2, Number>(q - a));
                const bool p_in = value_of(sp) >= 0., q_in = value_of(sq) >= 0.;
                if (p_in)
                  result.push_back(p);
                if (p_in != q_in)
                  result.push_back(p + crossing_fraction(sp, sq, edge, q - p) * (q - p));
              }
          }
        return result;
      }

      /**
       * Removes the vertices of the closed polygon @p values (and the same
       * entries of @p numbers) that lie on the straight segment between
       * their neighbours, up to @p tolerance: the clipping leaves such
       * vertices where edges coincide up to round-off (a master node on a
       * slave rim that the master shares, a crossing of two collinear
       * chords, put anywhere along them by round-off over round-off), and
       * whether it does is decided by round-off. The region is the same
       * without them, but the fan integration of for_each_point() (its
       * centre, the vertex centroid, and its triangles) is not, and on
       * curved faces its error, far above round-off, then followed the
       * DoF numbering (current_kinematics_cylinders_3d_01). A vertex where
       * the polygon turns back (the zero-width joins of clip_convex()) is
       * not between its neighbours and stays.
       */
      template <typename Number>
      void
      remove_straight_vertices(std::vector<Point<2>>         &values,
                               std::vector<Point<2, Number>> &numbers,
                               const double                   tolerance)
      {
        for (bool removed = true; removed && values.size() > 3;)
          {
            removed = false;
            for (unsigned int k = 0; k < values.size(); ++k)
              {
                const unsigned int m = values.size();
                const Point<2>    &a = values[(k + m - 1) % m], &b = values[(k + 1) % m];
                const Tensor<1, 2> ab = b - a, av = values[k] - a;
                const double       length_ab = ab.norm();
                if (!(length_ab > 0.))
                  continue;
                const double along = (av * ab) / length_ab;
                if (std::abs(cross_2d(ab, av)) <= tolerance * length_ab && along > 0. &&
                    along < length_ab)
                  {
                    values.erase(values.begin() + k);
                    numbers.erase(numbers.begin() + k);
                    removed = true;
                    break;
                  }
              }
          }
      }

      /// Interpolated (not normalised) nodal normal field at @p xi.
      template <typename Face, typename Number>
      Tensor<1, 3, Number>
      interpolated_normal(const Face                              &face,
                          const std::vector<Tensor<1, 3, Number>> &normals,
                          const Point<2, Number>                  &xi)
      {
        AssertDimension(normals.size(), face.n_shape_nodes());
        Tensor<1, 3, Number> n;
        for (unsigned int k = 0; k < normals.size(); ++k)
          n += quad_shape_value_of(face.shape_degree(), k, xi) * normals[k];
        return n;
      }

      /// @p t / |t|, for double exactly t /= t.norm().
      template <typename Number>
      void
      normalise(Tensor<1, 3, Number> &t)
      {
        const Number norm = length(t);
        t /= norm;
      }

      /// The auxiliary plane of a slave face: through its centre, normal n0
      /// (the nodal normals interpolated there), spanned by e1 (the xi
      /// tangent made orthogonal to n0) and e2 = n0 x e1.
      template <typename Number>
      struct AuxiliaryPlaneOf
      {
        Point<3, Number>     origin;
        Tensor<1, 3, Number> normal, e1, e2;

        /// (e1, e2) coordinates of the projection of @p x along the normal.
        Point<2, Number>
        coordinates(const Point<3, Number> &x) const
        {
          return Point<2, Number>((x - origin) * e1, (x - origin) * e2);
        }
        Point<3, Number>
        point(const Point<2, Number> &u) const
        {
          return origin + u[0] * e1 + u[1] * e2;
        }
        /// The plane in double.
        AuxiliaryPlaneOf<double>
        values() const
        {
          if constexpr (std::is_same_v<Number, double>)
            return *this;
          else
            return {point_value(origin), vector_value(normal), vector_value(e1), vector_value(e2)};
        }
      };
      using AuxiliaryPlane = AuxiliaryPlaneOf<double>;

      template <typename Face, typename Number>
      AuxiliaryPlaneOf<Number>
      auxiliary_plane(const Face &slave, const std::vector<Tensor<1, 3, Number>> &normals)
      {
        AssertDimension(normals.size(), slave.n_shape_nodes());
        const Point<2, Number>   centre;
        AuxiliaryPlaneOf<Number> plane;
        for (unsigned int k = 0; k < normals.size(); ++k)
          plane.normal += quad_shape_value(slave.shape_degree(), k, Point<2>()) * normals[k];
        AssertThrow(value_of(length(plane.normal)) > 0.,
                    ExcMessage("The slave normals cancel at the face centre."));
        normalise(plane.normal);
        plane.origin        = slave.point(centre);
        const auto tangents = slave.tangents(centre);
        plane.e1            = tangents[0] - (tangents[0] * plane.normal) * plane.normal;
        normalise(plane.e1);
        plane.e2 = cross_product_3d(plane.normal, plane.e1);
        return plane;
      }

      /**
       * The parameter of the point of @p face that @p x moved along @p d
       * reaches, whose value @p eta project_along() found on the face in
       * double (@p face_values). For an AD number: one Newton step in AD
       * numbers from (eta, t) on r = face(eta) - x - t d, whose derivative
       * part is that of the root (implicit-function theorem, as
       * implicit_root() in 2D); its value is set back to @p eta.
       */
      template <typename Face, typename Number>
      Point<2, Number>
      projected_parameter(const Face                 &face,
                          const QuadFace             &face_values,
                          const Point<3, Number>     &x,
                          const Tensor<1, 3, Number> &d,
                          const Point<2>             &eta)
      {
        if constexpr (std::is_same_v<Number, double>)
          return eta;
        else
          {
            const auto         t  = face_values.tangents(eta);
            const Tensor<1, 3> dv = vector_value(d);
            Tensor<2, 3>       J;
            for (unsigned int i = 0; i < 3; ++i)
              {
                J[i][0] = t[0][i];
                J[i][1] = t[1][i];
                J[i][2] = -dv[i];
              }
            const Tensor<2, 3>   J_inverse = invert(J);
            Tensor<1, 3, Number> r         = face.point(eta) - x;
            const double         along     = (vector_value(r) * dv) / dv.norm_square();
            r -= along * d;
            Point<2, Number> result;
            for (unsigned int c = 0; c < 2; ++c)
              {
                Number step = 0.;
                for (unsigned int i = 0; i < 3; ++i)
                  step += J_inverse[c][i] * r[i];
                result[c]       = eta[c] - step;
                result[c].val() = eta[c];
              }
            return result;
          }
      }

      /// A chord of the slave's projected boundary ring: the straight line
      /// between two consecutive ring nodes a and b in the plane, standing in
      /// for the part of a face edge between their parameters xi_a and xi_b.
      struct BoundaryChord
      {
        Point<2> a, b, xi_a, xi_b;
      };

      /// The point of @p face at the boundary parameter @p xi: its node
      /// where it has one there (bit for bit), else from the shapes.
      template <typename Face>
      auto
      boundary_point(const Face &face, const Point<2> &xi)
      {
        for (const unsigned int i : boundary_ring(face.degree()))
          if (quad_node_parameter(face.degree(), i) == xi)
            return face.nodes[i];
        return face.point(xi);
      }

      /// The chords of the slave's boundary ring given by its parameters
      /// @p boundary (boundary_parameters()).
      std::vector<BoundaryChord>
      boundary_chords(const QuadFace              &slave,
                      const AuxiliaryPlane        &plane,
                      const std::vector<Point<2>> &boundary)
      {
        std::vector<BoundaryChord> chords;
        for (unsigned int k = 0; k < boundary.size(); ++k)
          {
            const Point<2> &xi_a = boundary[k], &xi_b = boundary[(k + 1) % boundary.size()];
            chords.push_back({plane.coordinates(boundary_point(slave, xi_a)),
                              plane.coordinates(boundary_point(slave, xi_b)), xi_a, xi_b});
          }
        return chords;
      }

      /**
       * The boundary ring of the slave face as parameters, counterclockwise
       * in them: its boundary nodes, and on a curved face also points of a
       * face edge near each of the @p master_nodes that lies between that
       * edge and its chord (in the lens that the chord cuts off, or adds). Clipped by the chords alone, the overlap would lose a master
       * corner there (or keep one outside the face), and the crossings of
       * its master edges with the face edge (edge_crossing()) would lie on
       * their continuations beyond it: 3e-6 of a sphere's rim face doubled
       * (sphere-x100 of bench/stability). With the points added the corner
       * lies on the right side of the new chords: a convex edge's lenses
       * only shrink.
       */
      std::vector<Point<2>>
      boundary_parameters(const QuadFace              &slave,
                          const AuxiliaryPlane        &plane,
                          const std::vector<Point<3>> &master_nodes)
      {
        std::vector<Point<2>> boundary;
        for (const unsigned int i : boundary_ring(slave.degree()))
          boundary.push_back(quad_node_parameter(slave.degree(), i));
        if (slave.degree() == 1)
          return boundary;
        const Point<2> centre = plane.coordinates(slave.point(Point<2>()));
        // Whether the node x (at v in the plane) lies in the lens of the
        // chord: between it and the face edge, whose farthest point is at
        // the chord's middle parameter (a parabola).
        const auto in_lens = [&](const BoundaryChord &chord, const Point<3> &x, const Point<2> &v) {
          const Tensor<1, 2> c      = chord.b - chord.a;
          const double       length = c.norm();
          const double       sag =
            cross_2d(c, plane.coordinates(slave.point(0.5 * (chord.xi_a + chord.xi_b))) - chord.a) /
            length;
          const double fraction = ((v - chord.a) * c) / (length * length);
          const double offset   = cross_2d(c, v - chord.a) / length;
          if (!(fraction > 0. && fraction < 1.) || !(offset * sag > 0.) ||
              std::abs(offset) > std::abs(sag) || std::abs(offset) <= 1e-10 * length)
            return false;
          // Between chord and edge: on the edge's inner side (the inside
          // of the face) exactly where the chord bulges inward.
          Point<2> xi;
          if (!project_along(slave, x, plane.normal, xi))
            return false;
          const unsigned int fixed = chord.xi_a[0] == chord.xi_b[0] ? 0 : 1, free = 1 - fixed;
          const bool         inside_face = std::abs(xi[fixed]) < 1.;
          const bool         inside_chord =
            std::signbit(offset) == std::signbit(cross_2d(c, centre - chord.a));
          return inside_face != inside_chord && std::abs(std::abs(xi[fixed]) - 1.) > 1e-10 &&
                 (xi[free] - chord.xi_a[free]) * (xi[free] - chord.xi_b[free]) < 0.;
        };
        // The chord's middle parameter added until the node leaves the
        // lenses (each halving quarters the sag): fixed parameters, which
        // do not move with the configuration, so that the derivatives of
        // the overlap (AD numbers) need none of theirs. (The edge point
        // next to the node instead moved with it, and the quadrature error
        // of the fan integration with that point: the derivative check of
        // contact_interface_linearisation_02 lost its second order.)
        for (const Point<3> &x : master_nodes)
          {
            const Point<2> v = plane.coordinates(x);
            for (unsigned int depth = 0; depth < 20; ++depth)
              {
                const std::vector<BoundaryChord> chords = boundary_chords(slave, plane, boundary);
                unsigned int                     k      = 0;
                while (k < chords.size() && !in_lens(chords[k], x, v))
                  ++k;
                if (k == chords.size())
                  break;
                boundary.insert(boundary.begin() + k + 1, 0.5 * (chords[k].xi_a + chords[k].xi_b));
              }
          }
        return boundary;
      }

      /**
       * The slave parameter of a vertex @p u of an overlap piece that the
       * clipping put inside a @p chord, where the piece leaves the chord
       * along a master edge (the straight line from @p u to @p other): the
       * point where that master edge crosses the face edge of the chord.
       * Mapped back along n0 instead, @p u would land inside the face by the
       * chord's sag, the piece's edge along the chord would no longer be a
       * face edge for for_each_point(), and the lens between chord and edge
       * would be lost (on a sphere: 1e-4 of a face that a master edge
       * crosses, and 0.1 % of D at a slave corner cut off by a master edge
       * under the slightest initial penetration, a jump at zero gap).
       *
       * The projected face edge is a polynomial of degree <= 2 in its
       * parameter, so is the side f(s) = d x (P(s) - u) of its points:
       * monotone on either side of its extremum. Every crossing on the
       * whole face edge is found (bisection on the monotone parts) and the
       * one nearest to @p u taken. (A bracket from the chord's fraction at
       * the vertex before, taken as a parameter, missed it where the edge's
       * parameter runs unevenly along the chord: 5e-7 of a sphere's rim face
       * lost under a master corner near the rim, sphere-x100 of
       * bench/stability.) @p s: the crossing's fraction along the chord's
       * parameters (xi = xi_a + s (xi_b - xi_a)). False if the master edge
       * does not cross the face edge.
       */
      bool
      edge_crossing(const QuadFace       &slave,
                    const AuxiliaryPlane &plane,
                    const BoundaryChord  &chord,
                    const Point<2>       &u,
                    const Point<2>       &other,
                    Point<2>             &xi,
                    double               &s)
      {
        const Tensor<1, 2> d = other - u, dxi = chord.xi_b - chord.xi_a;
        const auto         edge_point = [&](const double s) {
          return plane.coordinates(slave.point(chord.xi_a + s * dxi));
        };
        const auto side = [&](const double s) { return cross_2d(d, edge_point(s) - u); };
        // The parameters s of the whole face edge: its free coordinate in
        // [-1, 1].
        const unsigned int c  = std::abs(dxi[0]) > std::abs(dxi[1]) ? 0 : 1;
        double             s0 = (-1. - chord.xi_a[c]) / dxi[c], s2 = (1. - chord.xi_a[c]) / dxi[c];
        if (s0 > s2)
          std::swap(s0, s2);
        // f(s) = a s^2 + b s + f(s0) around s0, from three values.
        const double h = s2 - s0, f0 = side(s0), f1 = side(s0 + 0.5 * h), f2 = side(s2);
        const double a = 2. * (f2 - 2. * f1 + f0) / (h * h), b = (4. * f1 - 3. * f0 - f2) / h;
        std::vector<double> ends = {s0};
        if (a != 0. && -b / (2. * a) > 0. && -b / (2. * a) < h)
          ends.push_back(s0 - b / (2. * a));
        ends.push_back(s2);
        bool   found    = false;
        double distance = 0.;
        for (unsigned int k = 0; k + 1 < ends.size(); ++k)
          {
            double     lower = ends[k], upper = ends[k + 1];
            const bool inner = side(lower) > 0.;
            if ((side(upper) > 0.) == inner)
              continue;
            // Down to adjacent numbers (s may reach beyond [0, 1]: the
            // chord may be a part of the edge).
            for (double middle = 0.5 * (lower + upper); middle != lower && middle != upper;
                 middle        = 0.5 * (lower + upper))
              ((side(middle) > 0.) == inner ? lower : upper) = middle;
            const double root = 0.5 * (lower + upper);
            if (!found || edge_point(root).distance(u) < distance)
              {
                found    = true;
                distance = edge_point(root).distance(u);
                s        = root;
              }
          }
        if (!found)
          return false;
        // dxi is zero in the edge's fixed parameter, which stays exactly +-1.
        xi = chord.xi_a + s * dxi;
        return true;
      }

      /// Calls f(xi, jxw) for the quadrature points of the given polygons of
      /// slave parameters; jxw is the weight times the slave area element.
      ///
      /// The polygons come from clipping in the auxiliary plane, so their
      /// edges are straight there, and they are integrated there: cut into
      /// triangles fanning out from the vertex centroid, every point mapped
      /// back along n0 to the slave. That makes the region exact for every
      /// flat face (straight edges in the slave parameters instead were off
      /// by 4 % of the area on quadrilaterals with corners moved by 10 % of
      /// their size). Edges on the slave boundary, though, follow the face:
      /// straight in the parameters, so the whole of a curved face (whose
      /// projected edges bend) is covered exactly too.
      ///
      /// Each triangle (c, E(v)), E the edge, is integrated by the collapsed
      /// Gauss rule x = c + u (E(v) - c), dA = u |(E - c) x E'| du dv, n x n
      /// points: exact for polynomials of total degree 2 n - 2 on straight
      /// triangles, and of any order, which QGaussSimplex<2> of deal.II 9.4
      /// is not. Signed weights: polygons star-shaped from their centroid,
      /// convex or not, are exact too.
      template <typename Face, typename Number, typename Function>
      void
      for_each_point(const Face                                    &slave,
                     const QuadFace                                &slave_values,
                     const AuxiliaryPlaneOf<Number>                &plane,
                     const std::vector<ParameterPolygonOf<Number>> &polygons,
                     const unsigned int                             n,
                     const Function                                &f)
      {
        const QGauss<1>               gauss(n);
        const AuxiliaryPlane          plane_values = plane.values();
        std::vector<Point<2, Number>> vertices;
        for (const ParameterPolygonOf<Number> &polygon : polygons)
          {
            const unsigned int m = polygon.size();
            vertices.clear();
            Point<2, Number> c;
            Number           area = 0.;
            for (const Point<2, Number> &xi : polygon)
              {
                vertices.push_back(plane.coordinates(slave.point(xi)));
                c += vertices.back() / static_cast<double>(m);
              }
            for (unsigned int k = 0; k < m; ++k)
              area += cross_2d(vertices[k], vertices[(k + 1) % m]);
            // Counterclockwise in the slave parameters, but clockwise in the
            // plane if the slave parameters run clockwise seen from n0.
            const double orientation = value_of(area) < 0. ? -1. : 1.;
            for (unsigned int k = 0; k < m; ++k)
              {
                const Point<2, Number> xa = polygon[k], xb = polygon[(k + 1) % m];
                // On the slave boundary: both ends on the same line xi = +-1
                // or eta = +-1 (overlap() clamps them there).
                bool on_boundary = false;
                for (unsigned int d = 0; d < 2; ++d)
                  on_boundary |=
                    (std::abs(value_of(xa[d])) == 1. && value_of(xb[d]) == value_of(xa[d]));
                for (unsigned int j = 0; j < n; ++j)
                  {
                    const double         v = gauss.point(j)[0];
                    Point<2, Number>     E;
                    Tensor<1, 2, Number> dE;
                    if (on_boundary)
                      {
                        const Point<2, Number>     xi = xa + v * (xb - xa);
                        const auto                 t  = slave.tangents(xi);
                        const Tensor<1, 3, Number> T  = (xb - xa)[0] * t[0] + (xb - xa)[1] * t[1];
                        E                             = plane.coordinates(slave.point(xi));
                        dE[0]                         = T * plane.e1;
                        dE[1]                         = T * plane.e2;
                      }
                    else
                      {
                        E  = vertices[k] + v * (vertices[(k + 1) % m] - vertices[k]);
                        dE = vertices[(k + 1) % m] - vertices[k];
                      }
                    const Number det = orientation * cross_2d(Tensor<1, 2, Number>(E - c), dE);
                    if (value_of(det) == 0.)
                      continue;
                    for (unsigned int i = 0; i < n; ++i)
                      {
                        const double           u = gauss.point(i)[0];
                        const Point<3, Number> x = plane.point(c + u * (E - c));
                        Point<2>               xi_value;
                        if (!project_along(slave_values, point_value(x), plane_values.normal,
                                           xi_value))
                          continue;
                        const Point<2, Number> xi = clamped(
                          projected_parameter(slave, slave_values, x, plane.normal, xi_value));
                        // Plane area to slave area: |t_xi x t_eta| / |n0 . (t_xi x t_eta)|.
                        const auto                 t  = slave.tangents(xi);
                        const Tensor<1, 3, Number> nt = cross_product_3d(t[0], t[1]);
                        const Number jxw = gauss.weight(i) * gauss.weight(j) * u * det *
                                           length(nt) / abs_of(Number(nt * plane.normal));
                        f(xi, jxw);
                      }
                  }
              }
          }
      }

      /// Whether @p quad is a flat parallelogram with its nodes where the
      /// bilinear map of its vertices puts them.
      bool
      is_parallelogram(const QuadFace &quad)
      {
        const auto  &x         = quad.nodes;
        const double tolerance = 1e-12 * x[0].distance(x[3]);
        // Differences first: the round-off is then that of the face's size,
        // not of its distance from the origin.
        if (((x[3] - x[1]) - (x[2] - x[0])).norm() > tolerance)
          return false;
        for (unsigned int k = 4; k < x.size(); ++k)
          {
            const Point<2> xi = quad_node_parameter(2, k);
            Tensor<1, 3>   bilinear;
            for (unsigned int v = 1; v < 4; ++v)
              bilinear += quad_shape_value(1, v, xi) * (x[v] - x[0]);
            if (((x[k] - x[0]) - bilinear).norm() > tolerance)
              return false;
          }
        return true;
      }
    } // namespace

    Tensor<1, 2>
    quad_shape_gradient(const unsigned int p, const unsigned int i, const Point<2> &xi)
    {
      const auto [a, b] = quad_line_indices(p, i);
      Tensor<1, 2> g;
      g[0] = lagrange_derivative(p, a, xi[0]) * lagrange_value(p, b, xi[1]);
      g[1] = lagrange_value(p, a, xi[0]) * lagrange_derivative(p, b, xi[1]);
      return g;
    }

    Point<2>
    quad_node_parameter(const unsigned int p, const unsigned int i)
    {
      const auto [a, b] = quad_line_indices(p, i);
      return Point<2>(node_parameter(p, a), node_parameter(p, b));
    }

    Point<3>
    QuadFace::point(const Point<2> &xi) const
    {
      Assert(nodes.size() == 4 || nodes.size() == 9, ExcNotImplemented());
      // The 1D shapes once per direction (the nodes share them).
      const unsigned int    p = degree();
      std::array<double, 3> l0, l1;
      for (unsigned int a = 0; a <= p; ++a)
        {
          l0[a] = lagrange_value(p, a, xi[0]);
          l1[a] = lagrange_value(p, a, xi[1]);
        }
      Point<3> x;
      for (unsigned int i = 0; i < nodes.size(); ++i)
        {
          const auto [a, b] = quad_line_indices(p, i);
          x += (l0[a] * l1[b]) * nodes[i];
        }
      return x;
    }

    std::array<Tensor<1, 3>, 2>
    QuadFace::tangents(const Point<2> &xi) const
    {
      Assert(nodes.size() == 4 || nodes.size() == 9, ExcNotImplemented());
      const unsigned int    p = degree();
      std::array<double, 3> l0, l1, dl0, dl1;
      for (unsigned int a = 0; a <= p; ++a)
        {
          l0[a]  = lagrange_value(p, a, xi[0]);
          l1[a]  = lagrange_value(p, a, xi[1]);
          dl0[a] = lagrange_derivative(p, a, xi[0]);
          dl1[a] = lagrange_derivative(p, a, xi[1]);
        }
      std::array<Tensor<1, 3>, 2> t;
      for (unsigned int i = 0; i < nodes.size(); ++i)
        {
          const auto [a, b] = quad_line_indices(p, i);
          t[0] += (dl0[a] * l1[b]) * nodes[i];
          t[1] += (l0[a] * dl1[b]) * nodes[i];
        }
      return t;
    }

    Tensor<1, 3>
    face_normal(const QuadFace &face, const Point<2> &xi, const double orientation)
    {
      const auto         t = face.tangents(xi);
      const Tensor<1, 3> n = cross_product_3d(t[0], t[1]);
      return orientation * n / n.norm();
    }

    namespace
    {
      /// A = D_e M_e^{-1} from the sums over the points f(xi, jxw) visits.
      template <typename Rule>
      FullMatrix<double>
      dual_basis_from_rule(const QuadFace &slave, const Rule &for_each_point)
      {
        const unsigned int p = slave.shape_degree(), n = slave.n_shape_nodes();
        FullMatrix<double> Me(n, n), De(n, n);
        for_each_point([&](const Point<2> &xi, const double jxw) {
          for (unsigned int j = 0; j < n; ++j)
            {
              const double Nj = quad_shape_value(p, j, xi);
              De(j, j) += Nj * jxw;
              for (unsigned int k = 0; k < n; ++k)
                Me(j, k) += Nj * quad_shape_value(p, k, xi) * jxw;
            }
        });
        return dual_basis_from_integrals(De, Me);
      }
    } // namespace

    FullMatrix<double>
    dual_basis_from_integrals(const FullMatrix<double> &De, const FullMatrix<double> &Me)
    {
      const unsigned int n = De.m();
      FullMatrix<double> Me_inverse(n, n), A(n, n);
      Me_inverse.invert(Me);
      De.mmult(A, Me_inverse);
      return A;
    }

    FullMatrix<double>
    dual_basis_coefficients(const QuadFace &slave)
    {
      // Tensor Gauss on the parameter square: exact for flat parallelograms;
      // the Jacobian of other faces is not polynomial, hence the generous
      // rule (as in 2D).
      const QGauss<2> rule(2 * slave.shape_degree() + 8);
      return dual_basis_from_rule(slave, [&](const auto &f) {
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            const Point<2> xi(2. * rule.point(q)[0] - 1., 2. * rule.point(q)[1] - 1.);
            const auto     t = slave.tangents(xi);
            f(xi, 4. * rule.weight(q) * cross_product_3d(t[0], t[1]).norm());
          }
      });
    }

    FullMatrix<double>
    dual_basis_coefficients(const QuadFace                      &slave,
                            const std::vector<Tensor<1, 3>>     &slave_normals,
                            const std::vector<ParameterPolygon> &polygons)
    {
      Assert(!polygons.empty(), ExcMessage("The dual basis needs a non-empty overlap."));
      const AuxiliaryPlane plane = auxiliary_plane(slave, slave_normals);
      return dual_basis_from_rule(slave, [&](const auto &f) {
        for_each_point(slave, slave, plane, polygons, slave.shape_degree() + 5, f);
      });
    }

    double
    projected_area(const QuadFace                      &slave,
                   const std::vector<Tensor<1, 3>>     &slave_normals,
                   const std::vector<ParameterPolygon> &polygons)
    {
      // Green's theorem, area = 1/2 sum over the edges of (x dy - y dx), in
      // the auxiliary plane, where the overlap's edges are straight (and a
      // zero-width join of clip_convex() has no area), but for edges on the
      // slave boundary (both ends on xi = +-1 or on eta = +-1), which
      // follow the face: along such an edge the projected point is a
      // polynomial of degree <= 2 in its parameter, the integrand of degree
      // <= 3, which 3 Gauss points integrate exactly.
      const AuxiliaryPlane plane = auxiliary_plane(slave, slave_normals);
      const QGauss<1>      gauss(3);
      double               area = 0.;
      for (const ParameterPolygon &polygon : polygons)
        for (std::size_t k = 0; k < polygon.size(); ++k)
          {
            const Point<2> &a = polygon[k], &b = polygon[(k + 1) % polygon.size()];
            bool            on_boundary = false;
            for (unsigned int d = 0; d < 2; ++d)
              on_boundary |= std::abs(a[d]) == 1. && b[d] == a[d];
            if (!on_boundary)
              {
                area += 0.5 * cross_2d(plane.coordinates(slave.point(a)),
                                       plane.coordinates(slave.point(b)));
                continue;
              }
            for (unsigned int q = 0; q < gauss.size(); ++q)
              {
                const double   s = gauss.point(q)[0];
                const Point<2> x = plane.coordinates(slave.point(a + s * (b - a)));
                // d/ds of the projected point, by the face's tangents.
                const Tensor<1, 3> dx_3d = slave.tangents(a + s * (b - a))[0] * (b[0] - a[0]) +
                                           slave.tangents(a + s * (b - a))[1] * (b[1] - a[1]);
                const Tensor<1, 2> dx({dx_3d * plane.e1, dx_3d * plane.e2});
                area += 0.5 * gauss.weight(q) * (x[0] * dx[1] - x[1] * dx[0]);
              }
          }
      return area;
    }

    bool
    project_along(const QuadFace     &face,
                  const Point<3>     &x,
                  const Tensor<1, 3> &direction,
                  Point<2>           &eta)
    {
      // Residual r(eta, t) = face(eta) - x - t d; linear in eta and t for
      // flat parallelograms, bilinear (or biquadratic) otherwise. It is
      // formed from the differences x_i - x, so that its round-off is that
      // of the face's size, not of the coordinates' distance from the
      // origin; Newton then reaches a parameter step of round-off size.
      // On the stack: project_along() runs for every quadrature point.
      AssertIndexRange(face.nodes.size(), 10);
      const unsigned int          n_nodes = face.nodes.size(), p = face.degree();
      std::array<Tensor<1, 3>, 9> offsets;
      for (unsigned int i = 0; i < n_nodes; ++i)
        offsets[i] = face.nodes[i] - x;
      eta              = Point<2>();
      double t         = 0.;
      double last_step = std::numeric_limits<double>::max();
      for (unsigned int it = 0; it < 30; ++it)
        {
          const auto   tangents = face.tangents(eta);
          Tensor<1, 3> r        = -t * direction;
          for (unsigned int i = 0; i < n_nodes; ++i)
            r += quad_shape_value(p, i, eta) * offsets[i];
          Tensor<2, 3> J;
          for (unsigned int i = 0; i < 3; ++i)
            {
              J[i][0] = tangents[0][i];
              J[i][1] = tangents[1][i];
              J[i][2] = -direction[i];
            }
          const double scale = tangents[0].norm() * tangents[1].norm() * direction.norm();
          if (!(std::abs(determinant(J)) > 1e-12 * scale))
            return false;
          const Tensor<1, 3> step = invert(J) * r;
          eta[0] -= step[0];
          eta[1] -= step[1];
          t -= step[2];
          if (!(std::abs(eta[0]) < 1e3 && std::abs(eta[1]) < 1e3))
            return false;
          // Converged at a step of round-off size, or where the step stops
          // shrinking at a size that only round-off explains.
          const double     size      = std::abs(step[0]) + std::abs(step[1]);
          constexpr double round_off = 64. * std::numeric_limits<double>::epsilon();
          if (size < 1e-13 ||
              (size < round_off * (1. + std::abs(eta[0]) + std::abs(eta[1])) * 1e3 &&
               size >= 0.5 * last_step))
            return true;
          last_step = size;
        }
      return false;
    }

    namespace
    {
      /// The convex @p pieces of a slave ring (convex_pieces(), in double)
      /// in numbers of type Number: their vertices are those of @p ring
      /// or its @p centre.
      template <typename Number>
      std::vector<std::vector<Point<2, Number>>>
      pieces_of(const std::vector<PlanePolygon>     &pieces,
                const std::vector<Point<2, Number>> &ring,
                const Point<2, Number>              &centre)
      {
        if constexpr (std::is_same_v<Number, double>)
          return pieces;
        else
          {
            std::vector<std::vector<Point<2, Number>>> result;
            for (const PlanePolygon &piece : pieces)
              {
                result.emplace_back();
                for (const Point<2> &u : piece)
                  {
                    result.back().push_back(centre);
                    for (const Point<2, Number> &r : ring)
                      if (point_value(r) == u)
                        result.back().back() = r;
                  }
              }
            return result;
          }
      }

      /// The slave parameter of the overlap vertex @p u (in the auxiliary
      /// plane), whose value @p xi_value overlap() found: its projection
      /// along n0 in numbers of type Number, a coordinate on the slave
      /// boundary held there. Exact for bilinear faces, whose edges project
      /// to the chords (a crossing of a curved edge: crossing_parameter()).
      /// @p projected: the projection before overlap() put it on the
      /// boundary, where the implicit-function step is taken. A vertex
      /// between a boundary chord and a curved edge that bends inward
      /// projects outside the face (a master node just inside the chord:
      /// the rim of a hanging master edge whose chords differ from its
      /// neighbour's) and is put on the boundary; the step taken there
      /// instead of at the projection gave the free coordinate the
      /// derivative of another point (errors of 1e-3 of D's scale).
      template <typename Face, typename Number>
      Point<2, Number>
      vertex_parameter(const Face                     &slave,
                       const QuadFace                 &slave_values,
                       const AuxiliaryPlaneOf<Number> &plane,
                       const Point<2, Number>         &u,
                       const Point<2>                 &xi_value,
                       const Point<2>                 &projected)
      {
        if constexpr (std::is_same_v<Number, double>)
          return xi_value;
        else
          {
            Point<2, Number> xi =
              projected_parameter(slave, slave_values, plane.point(u), plane.normal, projected);
            for (unsigned int d = 0; d < 2; ++d)
              {
                if (std::abs(xi_value[d]) == 1.)
                  xi[d] = Number(xi_value[d]);
                xi[d].val() = xi_value[d];
              }
            return xi;
          }
      }

      /// A vertex that overlap() put where a master edge crosses a slave
      /// edge (edge_crossing()): its chord, the fraction s along it, and
      /// which neighbour of the vertex spans that master edge with it.
      struct EdgeCrossing
      {
        bool         found         = false;
        unsigned int chord         = 0;
        double       s             = 0.;
        bool         other_is_next = false;
      };

      /**
       * The slave parameter of an edge @p crossing (value @p xi_value) in
       * numbers of type Number, from the overlap vertex @p u and its
       * neighbour @p other along the master edge. The crossing solves
       * f(s) = d x (P(x(xi_a + s dxi)) - u) = 0, d = other - u, P the plane
       * coordinates, x the slave face; found by bisection in double, its
       * derivatives come from the implicit-function theorem: one Newton step
       * s* - f(s*) / f_s(s*) in AD numbers (f_s in double) carries
       * ds = -f_x dx / f_s, and its value is set back to s*. A coordinate on
       * the slave boundary (+-1) is held, as in vertex_parameter().
       */
      template <typename Face, typename Number>
      Point<2, Number>
      crossing_parameter(const Face                     &slave,
                         const QuadFace                 &slave_values,
                         const AuxiliaryPlaneOf<Number> &plane,
                         const BoundaryChord            &chord,
                         const EdgeCrossing             &crossing,
                         const Point<2, Number>         &u,
                         const Point<2, Number>         &other,
                         const Point<2>                 &xi_value)
      {
        if constexpr (std::is_same_v<Number, double>)
          return xi_value;
        else
          {
            const Tensor<1, 2>         dxi  = chord.xi_b - chord.xi_a;
            const Point<2>             xi_s = chord.xi_a + crossing.s * dxi;
            const Tensor<1, 2, Number> d    = other - u;
            const Number               f =
              cross_2d(d, Tensor<1, 2, Number>(plane.coordinates(slave.point(xi_s)) - u));
            const auto           t            = slave_values.tangents(xi_s);
            const Tensor<1, 3>   T            = dxi[0] * t[0] + dxi[1] * t[1];
            const AuxiliaryPlane plane_values = plane.values();
            const Tensor<1, 2>   dT({T * plane_values.e1, T * plane_values.e2});
            const Tensor<1, 2>   d_value = point_value(d);
            const double         f_s     = cross_2d(d_value, dT);
            // A master edge (nearly) tangent to the slave edge: the crossing
            // is ill-conditioned; hold s (as crossing_fraction() does).
            Number s = crossing.s;
            if (std::abs(f_s) > 1e-10 * d_value.norm() * dT.norm())
              s = crossing.s - f / f_s;
            Point<2, Number> xi;
            for (unsigned int c = 0; c < 2; ++c)
              {
                xi[c] = chord.xi_a[c] + s * dxi[c];
                if (std::abs(xi_value[c]) == 1. || dxi[c] == 0.)
                  xi[c] = Number(xi_value[c]);
                xi[c].val() = xi_value[c];
              }
            return xi;
          }
      }

      /// The parameter (in double) of the vertex @p u of an overlap
      /// @p piece after @p prev and before @p next (overlap()): where a
      /// master edge crosses the slave edge for a vertex inside a boundary
      /// chord (described in @p crossing), the projection along n0
      /// otherwise, put on the boundary within 1e-10 or beyond it; @p
      /// projected: the parameter before that.
      /// False if it does not project.
      bool
      vertex_parameter_value(const QuadFace                   &slave,
                             const AuxiliaryPlane             &plane,
                             const std::vector<BoundaryChord> &chords,
                             const Point<2>                   &u,
                             const Point<2>                   &prev,
                             const Point<2>                   &next,
                             Point<2>                         &xi,
                             Point<2>                         &projected,
                             EdgeCrossing                     &crossing)
      {
        // A vertex inside a boundary chord, between a neighbour on the
        // chord and one off it: where a master edge crosses the slave
        // edge.
        crossing = EdgeCrossing();
        for (unsigned int k = 0; k < chords.size(); ++k)
          {
            const BoundaryChord &chord   = chords[k];
            const Tensor<1, 2>   c       = chord.b - chord.a;
            const auto           on_line = [&](const Point<2> &x) {
              return std::abs(cross_2d(c, x - chord.a)) <= 1e-10 * c.norm_square();
            };
            const double fraction = ((u - chord.a) * c) / c.norm_square();
            if (!on_line(u) || !(fraction > 1e-10 && fraction < 1. - 1e-10) ||
                on_line(prev) == on_line(next))
              continue;
            crossing.chord         = k;
            crossing.other_is_next = on_line(prev);
            const Point<2> &other  = on_line(prev) ? next : prev;
            crossing.found         = edge_crossing(slave, plane, chord, u, other, xi, crossing.s);
            break;
          }
        if (!crossing.found && !project_along(slave, plane.point(u), plane.normal, xi))
          return false;
        projected = xi;
        // Vertices on the slave boundary come back up to round-off:
        // put them on it (for_each_point() recognises its edges).
        for (unsigned int d = 0; d < 2; ++d)
          if (std::abs(xi[d]) > 1. - 1e-10)
            xi[d] = xi[d] > 0. ? 1. : -1.;
        return true;
      }
    } // namespace

    template <typename Number>
    bool
    overlap_of(const QuadFaceFor<Number>               &slave,
               const QuadFace                          &slave_values,
               const std::vector<Tensor<1, 3, Number>> &slave_normals,
               const QuadFaceFor<Number>               &master,
               std::vector<ParameterPolygonOf<Number>> &polygons)
    {
      using Polygon = std::vector<Point<2, Number>>;
      polygons.clear();
      const AuxiliaryPlaneOf<Number> plane        = auxiliary_plane(slave, slave_normals);
      const AuxiliaryPlane           plane_values = plane.values();

      // Projection along n0 into the plane, in (e1, e2) coordinates,
      // counterclockwise (the master, whose normal opposes n0, comes
      // clockwise).
      const auto project = [&](const QuadFaceFor<Number> &face) {
        Polygon ring;
        for (const unsigned int i : boundary_ring(face.degree()))
          ring.push_back(plane.coordinates(face.nodes[i]));
        if (value_of(twice_signed_area(ring)) < 0.)
          std::reverse(ring.begin(), ring.end());
        return ring;
      };
      std::vector<Point<3>> master_nodes;
      for (const unsigned int i : boundary_ring(master.degree()))
        master_nodes.push_back(point_value(master.nodes[i]));
      const std::vector<Point<2>> boundary =
        boundary_parameters(slave_values, plane_values, master_nodes);
      Polygon slave_ring;
      for (const Point<2> &xi : boundary)
        slave_ring.push_back(plane.coordinates(boundary_point(slave, xi)));
      if (value_of(twice_signed_area(slave_ring)) < 0.)
        std::reverse(slave_ring.begin(), slave_ring.end());
      const Polygon master_ring = project(master);
      const double  slave_area = value_of(0.5 * twice_signed_area(slave_ring));
      PlanePolygon  slave_ring_values;
      for (const Point<2, Number> &u : slave_ring)
        slave_ring_values.push_back(point_value(u));
      // The master is clipped by the convex pieces of the slave: the slave
      // itself, or its fan from the centre where a curved edge bends inward
      // at its midpoint; their cuts run from node to node, so the slave edges
      // stay whole (for_each_point() integrates them along the face).
      const Point<2, Number>     centre = plane.coordinates(slave.point(Point<2, Number>()));
      const std::vector<Polygon> slave_pieces =
        pieces_of(convex_pieces(slave_ring_values, point_value(centre)), slave_ring, centre);
      // A master seen edge-on (or folded over) from the plane projects to no
      // valid polygon: no overlap to integrate.
      if (!(value_of(0.5 * twice_signed_area(master_ring)) > 1e-10 * slave_area) ||
          slave_pieces.empty())
        return false;

      const std::vector<BoundaryChord> chords =
        boundary_chords(slave_values, plane_values, boundary);
      const double                     length = std::sqrt(slave_area);
      for (const Polygon &slave_piece : slave_pieces)
        {
          const Polygon clipped = clip_convex(master_ring, slave_piece);
          // Touching edges or corners give no piece or a zero-area one;
          // slivers of this relative size are round-off of shared edges.
          if (clipped.size() < 3 ||
              !(value_of(0.5 * twice_signed_area(clipped)) > 1e-10 * slave_area))
            continue;
          // Clipping repeats a vertex that lies on a clip edge.
          Polygon      piece;
          PlanePolygon values;
          for (const Point<2, Number> &u : clipped)
            if (values.empty() || point_value(u).distance(values.back()) > 1e-12 * length)
              {
                piece.push_back(u);
                values.push_back(point_value(u));
              }
          while (values.size() > 1 && values.front().distance(values.back()) <= 1e-12 * length)
            {
              piece.pop_back();
              values.pop_back();
            }
          remove_straight_vertices(values, piece, 1e-10 * length);
          ParameterPolygonOf<Number> polygon;
          ParameterPolygon           polygon_values;
          for (unsigned int k = 0; k < piece.size(); ++k)
            {
              Point<2>           xi, projected;
              EdgeCrossing       crossing;
              const unsigned int prev = (k + values.size() - 1) % values.size(),
                                 next = (k + 1) % values.size();
              if (!vertex_parameter_value(slave_values, plane_values, chords, values[k],
                                          values[prev], values[next], xi, projected, crossing))
                {
                  polygons.clear();
                  return false;
                }
              // An edge crossing at a chord's end repeats its node. On a
              // bilinear face the crossing is the projection of the vertex
              // (straight edges), linearised as such.
              if (polygon_values.empty() || xi.distance(polygon_values.back()) > 1e-12)
                {
                  polygon_values.push_back(xi);
                  polygon.push_back(
                    crossing.found && slave_values.degree() == 2 ?
                      crossing_parameter(slave, slave_values, plane, chords[crossing.chord],
                                         crossing, piece[k],
                                         piece[crossing.other_is_next ? next : prev], xi) :
                      vertex_parameter(slave, slave_values, plane, piece[k], xi, projected));
                }
            }
          while (polygon_values.size() > 1 &&
                 polygon_values.front().distance(polygon_values.back()) <= 1e-12)
            {
              polygon_values.pop_back();
              polygon.pop_back();
            }
          if (polygon.size() < 3)
            continue;
          double area = 0.;
          for (std::size_t v = 0; v < polygon_values.size(); ++v)
            area += cross_2d(polygon_values[v], polygon_values[(v + 1) % polygon_values.size()]);
          // The slave's parameter orientation relative to n0 depends on its
          // vertex order (deal.II face orientation): make it counterclockwise.
          if (area < 0.)
            std::reverse(polygon.begin(), polygon.end());
          polygons.push_back(polygon);
        }
      return !polygons.empty();
    }

    bool
    overlap(const QuadFace                  &slave,
            const std::vector<Tensor<1, 3>> &slave_normals,
            const QuadFace                  &master,
            std::vector<ParameterPolygon>   &polygons)
    {
      return overlap_of<double>(slave, slave, slave_normals, master, polygons);
    }

    namespace
    {
      /// integrate_pair() on the given overlap @p polygons in numbers of
      /// type Number (see integrate_polygons_of()).
      template <typename Face, typename Number, typename Matrix, typename Operators>
      void
      integrate_polygons(const Face                                    &slave,
                         const QuadFace                                &slave_values,
                         const std::vector<Tensor<1, 3, Number>>       &slave_normals,
                         const Matrix                                  &dual_coefficients,
                         const Face                                    &master,
                         const QuadFace                                &master_values,
                         const unsigned int                             n_quadrature_points,
                         const std::vector<ParameterPolygonOf<Number>> &polygons,
                         Operators                                     &result,
                         QuadOperatorsOf<double>                       *basis = nullptr)
      {
        const unsigned int ps = slave.shape_degree(), pm = master.shape_degree();
        const unsigned int ns = slave.n_shape_nodes(), nm = master.n_shape_nodes();
        AssertDimension(dual_coefficients.n_rows(), ns);

        result.D.assign(ns, Number(0.));
        result.weighted_gap.assign(ns, Tensor<1, 3, Number>());
        // Filled explicitly: Table leaves the derivatives of a
        // FixedADNumber (SFad) uninitialised.
        result.M.reinit(ns, nm);
        for (unsigned int j = 0; j < ns; ++j)
          for (unsigned int l = 0; l < nm; ++l)
            result.M(j, l) = Number(0.);
        result.overlap_area = 0.;

        std::vector<Number> phi(ns);
        std::vector<double> basis_phi(ns);
        Table<2, double>    identity(ns, ns);
        if (basis)
          {
            // As integrate_polygons() with Number = double initialises them.
            basis->D.assign(ns, 0.);
            basis->weighted_gap.assign(ns, Tensor<1, 3>());
            basis->M.reinit(ns, nm);
            basis->overlap_area = 0.;
            for (unsigned int j = 0; j < ns; ++j)
              identity(j, j) = 1.;
          }
        const AuxiliaryPlaneOf<Number> plane = auxiliary_plane(slave, slave_normals);
        const auto add_point                 = [&](const Point<2, Number> &xi, const Number &jxw) {
          const Point<3, Number>     x_slave = slave.point(xi);
          const Tensor<1, 3, Number> n       = interpolated_normal(slave, slave_normals, xi);
          Point<2>                   eta_value;
          // The overlap's points project onto the master along n0 (the
          // segmentation's direction). Along n they may miss even the
          // master face's extension (beyond the fold of its map) where the
          // slave face is far from the master: a gap of a face size times
          // the normals' spread over the face (a sphere's steep flank above
          // a block). Such a point takes the projection along n0; near the
          // master both reach it. Skipping the point would shrink D.
          const bool along_n =
            project_along(master_values, point_value(x_slave), vector_value(n), eta_value);
          AssertThrow(along_n || project_along(master_values, point_value(x_slave),
                                               vector_value(plane.normal), eta_value),
                                      ExcMessage("Mortar integration: a quadrature point of the slave face "
                                                                 "centred at " +
                                                 coordinates_text(slave_values.point(Point<2>())) +
                                                 " does not project onto the master face centred at " +
                                                 coordinates_text(master_values.point(Point<2>())) + "."));
          // The segmentation projected along n0, the normal field may differ
          // slightly: stay on the master face (partition of unity kept).
          const Point<2, Number> eta =
            clamped(projected_parameter(master, master_values, x_slave, along_n ? n : plane.normal,
                                        eta_value));
          const Tensor<1, 3, Number> separation = master.point(eta) - x_slave;

          result.overlap_area += jxw;
          add_quadrature_point<3>(dual_coefficients, ps, pm, xi, eta, jxw, separation, phi, result);
          if constexpr (!std::is_same_v<Number, double>)
            if (basis)
              {
                // The double path's point: the values of this one.
                basis->overlap_area += jxw.val();
                add_quadrature_point<3>(identity, ps, pm, point_value(xi), point_value(eta),
                                        jxw.val(), vector_value(separation), basis_phi, *basis);
              }
        };
        for_each_point(slave, slave_values, plane, polygons, n_quadrature_points, add_point);
      }
    } // namespace

    bool
    integrate_pair(const QuadFace                  &slave,
                   const std::vector<Tensor<1, 3>> &slave_normals,
                   const FullMatrix<double>        &dual_coefficients,
                   const QuadFace                  &master,
                   const unsigned int               n_quadrature_points,
                   QuadSegmentOperators            &result)
    {
      if (!overlap(slave, slave_normals, master, result.polygons))
        return false;
      integrate_polygons(slave, slave, slave_normals, dual_coefficients, master, master,
                         n_quadrature_points, result.polygons, result);
      return result.overlap_area > 0.;
    }

    template <typename Number>
    void
    integrate_polygons_of(const QuadFaceFor<Number>                     &slave,
                          const QuadFace                                &slave_values,
                          const std::vector<Tensor<1, 3, Number>>       &slave_normals,
                          const Table<2, double>                        &dual_coefficients,
                          const QuadFaceFor<Number>                     &master,
                          const QuadFace                                &master_values,
                          const unsigned int                             n_quadrature_points,
                          const std::vector<ParameterPolygonOf<Number>> &polygons,
                          QuadOperatorsOf<Number>                       &result,
                          QuadOperatorsOf<double>                       *basis)
    {
      integrate_polygons(slave, slave_values, slave_normals, dual_coefficients, master,
                         master_values, n_quadrature_points, polygons, result, basis);
    }

    template <typename Number>
    void
    dual_basis_integrals_of(const QuadFaceFor<Number>                     &slave,
                            const QuadFace                                &slave_values,
                            const std::vector<Tensor<1, 3, Number>>       &slave_normals,
                            const std::vector<ParameterPolygonOf<Number>> &polygons,
                            Table<2, Number>                              &De,
                            Table<2, Number>                              &Me,
                            FullMatrix<double>                            *De_values,
                            FullMatrix<double>                            *Me_values)
    {
      const unsigned int  p = slave.shape_degree(), n = slave.n_shape_nodes();
      std::vector<Number> N(n);
      for_each_point(slave, slave_values, auxiliary_plane(slave, slave_normals), polygons, p + 5,
                     [&](const Point<2, Number> &xi, const Number &jxw) {
                       for (unsigned int k = 0; k < n; ++k)
                         N[k] = quad_shape_value_of(p, k, xi);
                       // M_e is symmetric: N_j N_k and N_k N_j are the same
                       // number (products and sums commute exactly).
                       for (unsigned int j = 0; j < n; ++j)
                         {
                           De(j, j) += N[j] * jxw;
                           for (unsigned int k = j; k < n; ++k)
                             Me(j, k) += N[j] * N[k] * jxw;
                         }
                       // The sums of dual_basis_from_rule(), in double.
                       if (De_values)
                         for (unsigned int j = 0; j < n; ++j)
                           {
                             const double Nj = value_of(N[j]), w = value_of(jxw);
                             (*De_values)(j, j) += Nj * w;
                             for (unsigned int k = 0; k < n; ++k)
                               (*Me_values)(j, k) += Nj * value_of(N[k]) * w;
                           }
                     });
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int k = 0; k < j; ++k)
          Me(j, k) = Me(k, j);
    }

    template bool
    overlap_of<double>(const QuadFace &,
                       const QuadFace &,
                       const std::vector<Tensor<1, 3>> &,
                       const QuadFace &,
                       std::vector<ParameterPolygon> &);
    template void
    integrate_polygons_of<double>(const QuadFace &,
                                  const QuadFace &,
                                  const std::vector<Tensor<1, 3>> &,
                                  const Table<2, double> &,
                                  const QuadFace &,
                                  const QuadFace &,
                                  const unsigned int,
                                  const std::vector<ParameterPolygon> &,
                                  QuadOperatorsOf<double> &,
                                  QuadOperatorsOf<double> *);
    template void
    dual_basis_integrals_of<double>(const QuadFace &,
                                    const QuadFace &,
                                    const std::vector<Tensor<1, 3>> &,
                                    const std::vector<ParameterPolygon> &,
                                    Table<2, double> &,
                                    Table<2, double> &,
                                    FullMatrix<double> *,
                                    FullMatrix<double> *);

    // The AD numbers of linearise_slave_face(), by the pair's number of
    // variables.
#define CONTACT_FEM_INSTANTIATE_AD(Number)                                                       \
  template bool overlap_of<Number>(const QuadFaceOf<Number> &, const QuadFace &,                 \
                                   const std::vector<Tensor<1, 3, Number>> &,                    \
                                   const QuadFaceOf<Number> &,                                   \
                                   std::vector<ParameterPolygonOf<Number>> &);                   \
  template void integrate_polygons_of<Number>(                                                   \
    const QuadFaceOf<Number> &, const QuadFace &, const std::vector<Tensor<1, 3, Number>> &,     \
    const Table<2, double> &, const QuadFaceOf<Number> &, const QuadFace &, const unsigned int,  \
    const std::vector<ParameterPolygonOf<Number>> &, QuadOperatorsOf<Number> &,                  \
    QuadOperatorsOf<double> *);                                                                  \
  template void dual_basis_integrals_of<Number>(const QuadFaceOf<Number> &, const QuadFace &,    \
                                                const std::vector<Tensor<1, 3, Number>> &,       \
                                                const std::vector<ParameterPolygonOf<Number>> &, \
                                                Table<2, Number> &, Table<2, Number> &,          \
                                                FullMatrix<double> *, FullMatrix<double> *)
    CONTACT_FEM_INSTANTIATE_AD(PairADNumber);
    CONTACT_FEM_INSTANTIATE_AD(CurvedPairADNumber);
    CONTACT_FEM_INSTANTIATE_AD(QuadraticPairADNumber);
#undef CONTACT_FEM_INSTANTIATE_AD

    Point<2>
    closest_parameter(const QuadFace &quad, const Point<3> &x)
    {
      constexpr double parameter_tolerance = 1e-13;
      Point<2>         xi;
      for (unsigned int it = 0; it < 30; ++it)
        {
          const auto         t = quad.tangents(xi);
          const Tensor<1, 3> r = x - quad.point(xi);
          const double       a = t[0] * t[0], b = t[0] * t[1], c = t[1] * t[1];
          const double       det = a * c - b * b;
          Point<2>           next(xi[0] + (c * (r * t[0]) - b * (r * t[1])) / det,
                                  xi[1] + (a * (r * t[1]) - b * (r * t[0])) / det);
          for (unsigned int held = 0; held < 2; ++held)
            if (std::abs(next[held]) > 1.)
              {
                next[held]               = next[held] > 0. ? 1. : -1.;
                const unsigned int along = 1 - held;
                next[along]              = std::clamp(next[along], -1., 1.);
                for (unsigned int k = 0; k < 20; ++k)
                  {
                    const Tensor<1, 3> tangent = quad.tangents(next)[along];
                    const double step = ((x - quad.point(next)) * tangent) / tangent.norm_square();
                    next[along]       = std::clamp(next[along] + step, -1., 1.);
                    if (std::abs(step) < parameter_tolerance)
                      break;
                  }
                break;
              }
          const bool done = next.distance(xi) < parameter_tolerance;
          xi              = next;
          if (done)
            break;
        }
      return xi;
    }

    BoundingBox<3>
    whole_face_box(const QuadFace &quad)
    {
      const double lebesgue_1d = lebesgue_constant(quad.degree());
      return interpolant_box(quad.nodes, lebesgue_1d * lebesgue_1d);
    }

    unsigned int
    n_quadrature_points(const QuadFace &slave, const QuadFace &master)
    {
      // Exact for parallelograms. Other faces map non-affinely (the master
      // parameter of a slave point is not polynomial): with 2 more points
      // the 3D patch test on trapezoid faces held to 5e-10 only, with 4 to
      // round-off (postprocess/patch_trapezoids_01), for about 2 % of the
      // 3D Hertz run's time.
      const unsigned int exact = 2 * slave.shape_degree() + 1;
      return is_parallelogram(slave) && is_parallelogram(master) ? exact : exact + 4;
    }

    std::vector<unsigned int>
    boundary_vertices(const Point<2> &xi)
    {
      const bool         on_xi = std::abs(xi[0]) == 1., on_eta = std::abs(xi[1]) == 1.;
      const unsigned int i = xi[0] > 0. ? 1 : 0, j = xi[1] > 0. ? 2 : 0;
      if (on_xi && on_eta)
        return {i + j};
      if (on_xi)
        return {i, i + 2};
      return {j, j + 1};
    }
  } // namespace Mortar
} // namespace contact_fem
