// The global numbers of a rank's own contact faces and of their nodes
// without the other ranks' faces (surface_numbering.h).
#include <contact_fem/contact/surface_numbering.h>

#include <boost/serialization/utility.hpp>

#include <algorithm>
#include <map>
#include <string>
#include <utility>

namespace contact_fem
{
  namespace
  {
    /// The sum of @p value over the ranks below this one, and over all.
    std::pair<unsigned int, unsigned int>
    exclusive_sum(unsigned int value, const MPI_Comm comm)
    {
      unsigned int below = 0;
      const int    ierr  = MPI_Exscan(&value, &below, 1, MPI_UNSIGNED, MPI_SUM, comm);
      AssertThrowMPI(ierr);
      // MPI_Exscan leaves rank 0's result undefined.
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        below = 0;
      return {below, Utilities::MPI::sum(value, comm)};
    }
  } // namespace

  OwnSurfaceNumbers
  number_own_faces(const std::vector<types::global_dof_index> &node_dofs,
                   const unsigned int                          nodes_per_face,
                   const IndexSet                             &owned_dofs,
                   const MPI_Comm                              comm)
  {
    // An error is thrown after the last collective call, so that a rank
    // that finds one does not leave the others waiting: the first found,
    // and how many there were.
    std::string  error;
    unsigned int n_errors = 0;
    const auto   note     = [&](const std::string &text) {
      if (n_errors++ == 0)
        error = text;
    };
    if (nodes_per_face == 0 || node_dofs.size() % nodes_per_face != 0)
      note("Contact: the node DoFs of the own faces are not whole faces.");
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int none = numbers::invalid_unsigned_int;
    OwnSurfaceNumbers  result;
    std::tie(result.first_face, result.n_faces) =
      exclusive_sum(nodes_per_face == 0 ? 0 : node_dofs.size() / nodes_per_face, comm);

    // This rank's distinct nodes, in the order of their first appearance.
    std::map<types::global_dof_index, unsigned int> local_of_dof;
    std::vector<types::global_dof_index>            distinct;
    std::vector<unsigned int>                       local_node(node_dofs.size());
    for (unsigned int i = 0; i < node_dofs.size(); ++i)
      {
        const auto inserted = local_of_dof.emplace(node_dofs[i], distinct.size());
        if (inserted.second)
          distinct.push_back(node_dofs[i]);
        local_node[i] = inserted.first->second;
      }

    // First exchange: every node's DoF to its owner, which answers with the
    // ranks naming it, ascending (some_to_some's map is by source rank).
    // deal.II's lookup of the owners, point to point (no range all-gathered).
    IndexSet looked_up(owned_dofs.size());
    looked_up.add_indices(distinct.begin(), distinct.end());
    looked_up.compress();
    const std::vector<unsigned int> owner_of =
      Utilities::MPI::compute_index_owner(owned_dofs, looked_up, comm);
    std::map<unsigned int, std::vector<types::global_dof_index>> asked;
    for (const auto dof : distinct)
      asked[owner_of[looked_up.index_within_set(dof)]].push_back(dof);
    std::map<unsigned int, std::vector<unsigned int>> answers;
    {
      const auto requests = Utilities::MPI::some_to_some(comm, asked);
      std::map<types::global_dof_index, std::vector<unsigned int>> naming;
      for (const auto &[source, dofs] : requests)
        for (const auto dof : dofs)
          naming[dof].push_back(source);
      // Per DoF asked: the number of naming ranks, then the ranks.
      for (const auto &[source, dofs] : requests)
        {
          auto &answer = answers[source];
          for (const auto dof : dofs)
            {
              const auto &ranks = naming[dof];
              answer.push_back(ranks.size());
              answer.insert(answer.end(), ranks.begin(), ranks.end());
            }
        }
    }
    const auto answered = Utilities::MPI::some_to_some(comm, answers);
    answers.clear();

    // The lowest naming rank of each node; for those this rank names
    // first, the other ranks naming them.
    std::vector<unsigned int>                          lowest(distinct.size(), none);
    std::vector<std::pair<unsigned int, unsigned int>> tell; // (node, rank)
    for (const auto &[owner_rank, dofs] : asked)
      {
        const auto  &answer   = answered.at(owner_rank);
        unsigned int position = 0;
        for (const auto dof : dofs)
          {
            const unsigned int n = answer.at(position);
            const unsigned int k = local_of_dof.at(dof);
            lowest[k]            = answer.at(position + 1);
            if (lowest[k] == rank)
              for (unsigned int j = 2; j <= n; ++j)
                tell.emplace_back(k, answer.at(position + j));
            position += 1 + n;
          }
      }

    // The nodes named first here, numbered after those of the lower ranks.
    std::vector<unsigned int> number(distinct.size(), none);
    unsigned int              n_first = 0;
    for (unsigned int k = 0; k < distinct.size(); ++k)
      if (lowest[k] == rank)
        number[k] = n_first++;
    unsigned int offset;
    std::tie(offset, result.n_nodes) = exclusive_sum(n_first, comm);
    for (auto &n : number)
      if (n != none)
        n += offset;

    // Second exchange: their numbers to the other ranks naming them, as
    // (DoF, number) pairs.
    std::map<unsigned int, std::vector<types::global_dof_index>> numbers_to;
    for (const auto &[k, to] : tell)
      {
        numbers_to[to].push_back(distinct[k]);
        numbers_to[to].push_back(number[k]);
      }
    for (const auto &[source, pairs] : Utilities::MPI::some_to_some(comm, numbers_to))
      for (unsigned int i = 0; i + 1 < pairs.size(); i += 2)
        {
          const auto it = local_of_dof.find(pairs[i]);
          if (it == local_of_dof.end() || lowest[it->second] != source ||
              number[it->second] != none)
            note("Contact: the number of the surface node of DoF " + std::to_string(pairs[i]) +
                 " came from rank " + std::to_string(source) + ", which does not name it first.");
          else
            number[it->second] = pairs[i + 1];
        }
    for (unsigned int k = 0; k < distinct.size(); ++k)
      if (number[k] == none)
        note("Contact: the surface node of DoF " + std::to_string(distinct[k]) + " got no number.");
    AssertThrow(n_errors == 0, ExcMessage(error + " (" + std::to_string(n_errors) +
                                          " such problems on rank " + std::to_string(rank) + ")"));

    result.nodes.resize(node_dofs.size());
    for (unsigned int i = 0; i < node_dofs.size(); ++i)
      result.nodes[i] = number[local_node[i]];
    return result;
  }
} // namespace contact_fem
