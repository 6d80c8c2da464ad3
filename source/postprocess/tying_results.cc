// The results of the tied pairs (Contact/Tied pairs), printed and recorded
// with each cycle's results.
#include <contact_fem/contact/mesh_tying.h>
#include <contact_fem/postprocess/postprocessor.h>

#include <ostream>

namespace contact_fem
{
  namespace
  {
    /// The tying results of each cycle (with tied pairs): the force, the
    /// traction range and the nodes per tied pair.
    template <int dim>
    class TyingResults : public Postprocessor<dim>
    {
    public:
      static std::unique_ptr<Postprocessor<dim>>
      create(const PostprocessorContext<dim> &context)
      {
        if (!context.has_tied_pairs)
          return nullptr;
        return std::make_unique<TyingResults<dim>>();
      }

      void
      after_cycle(const RunView<dim> &view, Json &cycle_record, std::ostream &out) override
      {
        cycle_record.set("tying", view.tying->results(out));
      }
    };
  } // namespace

  // Printed right after the contact results, before the other outputs.
  CONTACT_FEM_REGISTER_POSTPROCESSOR(TyingResults, "tying results", 0)

} // namespace contact_fem
