// What the postprocessors need to work from the rows a rank owns (issue 32
// item 1): the rows of a file gathered from the ranks, and vector sums in
// node order. A reader computes its rows or terms from the slave nodes
// whose rows it owns (ContactInterface::owns_row()) or from its own faces;
// these combine them exactly, so that no output depends on the partition.
#ifndef contact_fem_owned_rows_h
#define contact_fem_owned_rows_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <contact_fem/contact/contact_interface.h>

#include <utility>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /**
   * The rows of numbers each rank computed (@p mine), in rank order, on
   * rank 0 only (@p everywhere false; empty on the other ranks) or on
   * every rank. Exact copies; the rows may differ in length. Collective.
   */
  inline std::vector<std::vector<double>>
  gather_rows(const MPI_Comm                          comm,
              const std::vector<std::vector<double>> &mine,
              const bool                              everywhere)
  {
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      return mine;
    // Flat, each row as (length, values).
    std::vector<double> flat;
    for (const auto &row : mine)
      {
        flat.push_back(row.size());
        flat.insert(flat.end(), row.begin(), row.end());
      }
    const std::vector<std::vector<double>> chunks =
      everywhere ? Utilities::MPI::all_gather(comm, flat) : Utilities::MPI::gather(comm, flat, 0);
    std::vector<std::vector<double>> rows;
    for (const auto &chunk : chunks)
      for (std::size_t i = 0; i < chunk.size(); i += 1 + static_cast<std::size_t>(chunk[i]))
        rows.emplace_back(chunk.begin() + i + 1,
                          chunk.begin() + i + 1 + static_cast<std::size_t>(chunk[i]));
    return rows;
  }

  /**
   * The sum of vector @p terms (key, term) in key order, component by
   * component through ContactInterface::sum_in_node_order(): the key is the
   * index into slave_nodes (or any key whose order is the serial sum's), and
   * every rank gets the sum a rank holding every term gets, bit for bit.
   * `sum -= v` is `sum += (-v)` in floating point: a subtracted term may be
   * given negated. Collective.
   */
  template <int dim>
  Tensor<1, dim>
  sum_in_node_order(const ContactInterface<dim>                                &interface,
                    const std::vector<std::pair<unsigned int, Tensor<1, dim>>> &terms)
  {
    Tensor<1, dim> sum;
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::vector<std::pair<unsigned int, double>> component;
        component.reserve(terms.size());
        for (const auto &[key, term] : terms)
          component.emplace_back(key, term[d]);
        sum[d] = interface.sum_in_node_order(component);
      }
    return sum;
  }
} // namespace contact_fem

#endif
