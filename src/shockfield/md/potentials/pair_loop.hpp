#pragma once
// The threaded loops over a half neighbour list that every potential here shares (LAMMPS newton
// on: each pair once, both atoms updated, ghosts included). Threads take contiguous ranges of
// owned atoms holding about equal numbers of pairs; thread 0 adds into the caller's arrays, every
// other thread into a private zeroed copy, and the copies are added in thread order afterwards.
// No atomics, no races, and for a given thread count the result is reproducible; different
// thread counts differ only by the order of the sums (round-off).
#include <omp.h>

#include <algorithm>
#include <concepts>
#include <type_traits>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/geometry/neighbor_list.hpp"
#include "shockfield/md/atoms.hpp"
#include "shockfield/md/potential.hpp"

namespace shockfield::md::potentials {

/// A pair force model: for atoms i, j at squared distance rsq, returns false when the pair is
/// beyond its cutoff; otherwise sets fpair (force on i = (x_i - x_j) * fpair) and the pair energy.
template <class K>
concept PairForceKernel = requires(const K& k, int i, int j, double rsq, double& fpair,
                                   double& energy) {
  { k(i, j, rsq, fpair, energy) } -> std::same_as<bool>;
};

/// A pair force model whose force is not along the pair (ADP): for atoms i, j at d = x_i - x_j,
/// |d|² = rsq, returns false beyond its cutoff; otherwise sets fij (the force on i; j gets -fij)
/// and the pair energy.
template <class K>
concept PairVectorForceKernel = requires(const K& k, int i, int j, const Vec3& d, double rsq,
                                         Vec3& fij, double& energy) {
  { k(i, j, d, rsq, fij, energy) } -> std::same_as<bool>;
};

/// A pair density model (EAM's ρ, ADP's ρ, μ, λ): for atoms i, j at d = x_i - x_j, |d|² = rsq,
/// returns false beyond the cutoff, else what atom i receives from j (to_i) and j from i (to_j).
/// T is added with += and zeroed by T{}.
template <class K, class T>
concept PairScalarKernel = requires(const K& k, int i, int j, const Vec3& d, double rsq, T& to_i,
                                    T& to_j) {
  { k(i, j, d, rsq, to_i, to_j) } -> std::same_as<bool>;
};

/// Per-thread private copies of per-atom arrays, kept between calls to avoid reallocation.
struct ThreadScratch {
  std::vector<std::vector<Vec3>> force;
  std::vector<std::vector<double>> scalar;
  std::vector<std::vector<Voigt6>> virial;
};

/// The pairs of a half list that a potential's kernel accepted (within its cutoff), kept at their
/// places in the list: the neighbours of owned atom i are neighbors[list.offset[i], end[i]). A
/// many-body potential records them in its first pass so later passes skip the skin pairs.
struct AcceptedPairs {
  std::vector<int> neighbors;
  std::vector<std::int64_t> end;
};

namespace detail {

/// First owned atom of each thread's range (size nthreads + 1), balancing pair counts.
inline std::vector<std::size_t> thread_ranges(const geometry::NeighborList& list, int nthreads) {
  const std::size_t n = list.nlocal();
  std::vector<std::size_t> begin(static_cast<std::size_t>(nthreads) + 1, n);
  begin[0] = 0;
  const auto total = n == 0 ? 0 : list.offset[n];
  for (int t = 1; t < nthreads; ++t) {
    const auto target = total * t / nthreads;
    const auto it = std::lower_bound(list.offset.begin(), list.offset.end() - 1, target);
    begin[static_cast<std::size_t>(t)] = static_cast<std::size_t>(it - list.offset.begin());
  }
  return begin;
}

/// Thread t's accumulation array: the target itself for thread 0, else a zeroed private copy.
template <class T>
std::vector<T>& private_copy(std::vector<std::vector<T>>& copies, std::vector<T>& target, int t,
                             const std::type_identity_t<T>& zero) {
  if (t == 0) return target;
  auto& mine = copies[static_cast<std::size_t>(t)];
  mine.assign(target.size(), zero);
  return mine;
}

/// Adds the copies of threads 1.. into the target in thread order (call inside the parallel
/// region after a barrier; the atoms are shared out among the threads).
template <class T>
void reduce_copies(const std::vector<std::vector<T>>& copies, std::vector<T>& target, int nthreads) {
#pragma omp for schedule(static)
  for (std::size_t a = 0; a < target.size(); ++a)
    for (int t = 1; t < nthreads; ++t) target[a] += copies[static_cast<std::size_t>(t)][a];
}

}  // namespace detail

namespace detail {

// The pair loop of one thread over owned atoms [begin, end); PerAtom adds the LAMMPS per-atom
// split (half of each pair's energy and virial to each atom). The kernel is copied so its
// parameters stay in registers (the force stores could alias a referenced kernel).
// The neighbours of i are neighbors[first[i], last[i]).
template <bool PerAtom, class K>
void pair_force_range(const Vec3* x, const int* neighbors, const std::int64_t* first,
                      const std::int64_t* last, const K& kernel_ref, std::size_t begin,
                      std::size_t end, Vec3* f, double* eatom, Voigt6* vatom, double& energy) {
  const K kernel = kernel_ref;
  double e = 0;
  for (std::size_t i = begin; i < end; ++i) {
    const Vec3 xi = x[i];
    Vec3 fi = Vec3::Zero();
    for (auto k = first[i]; k < last[i]; ++k) {
      const int j = neighbors[k];
      const Vec3 d = xi - x[j];
      double epair;
      Vec3 fij;
      if constexpr (PairVectorForceKernel<K>) {
        if (!kernel(static_cast<int>(i), j, d, d.squaredNorm(), fij, epair)) continue;
      } else {
        double fpair;
        if (!kernel(static_cast<int>(i), j, d.squaredNorm(), fpair, epair)) continue;
        fij = d * fpair;
      }
      fi += fij;
      f[j] -= fij;
      e += epair;
      if constexpr (PerAtom) {
        Voigt6 half;
        half << d.x() * fij.x(), d.y() * fij.y(), d.z() * fij.z(), d.x() * fij.y(), d.x() * fij.z(),
            d.y() * fij.z();
        half *= 0.5;
        eatom[i] += 0.5 * epair;
        eatom[j] += 0.5 * epair;
        vatom[i] += half;
        vatom[j] += half;
      }
    }
    f[i] += fi;
  }
  energy = e;
}

// Σ_k x_k ⊗ f_k over owned and ghost entries: the virial Σ_pairs r_ij ⊗ f_ij of the pair forces
// held in f, since each pair adds f_ij at x_i and −f_ij at x_j (LAMMPS virial_fdotr_compute).
inline Voigt6 virial_fdotr(const Vec3* x, const Vec3* f, std::size_t n) {
  double vxx = 0, vyy = 0, vzz = 0, vxy = 0, vxz = 0, vyz = 0;
  for (std::size_t k = 0; k < n; ++k) {
    vxx += x[k].x() * f[k].x(); vyy += x[k].y() * f[k].y(); vzz += x[k].z() * f[k].z();
    vxy += x[k].x() * f[k].y(); vxz += x[k].x() * f[k].z(); vyz += x[k].y() * f[k].z();
  }
  Voigt6 v;
  v << vxx, vyy, vzz, vxy, vxz, vyz;
  return v;
}

}  // namespace detail

/// Adds the forces of `kernel` over the half list to atoms.f (owned and ghost entries, zero on
/// entry as Potential::compute() is promised), the pair energy and virial Σ r_ij ⊗ f_ij to `out`,
/// and with `out.per_atom` half of each pair's energy and virial to each atom (LAMMPS ev_tally
/// with newton on; ev_tally_xyz for a vector force). The total virial is Σ x ⊗ f of each thread's
/// forces, before they are summed. With `accepted` (recorded by accumulate_pair_scalars on the
/// same list and positions) only those pairs are visited.
template <class K>
  requires PairForceKernel<K> || PairVectorForceKernel<K>
void accumulate_pair_forces(Atoms& atoms, const geometry::NeighborList& list, const K& kernel,
                            ForceResult& out, ThreadScratch& scratch,
                            const AcceptedPairs* accepted = nullptr) {
  const int nthreads = omp_get_max_threads();
  const auto range = detail::thread_ranges(list, nthreads);
  scratch.force.resize(static_cast<std::size_t>(nthreads));
  scratch.scalar.resize(static_cast<std::size_t>(nthreads));
  scratch.virial.resize(static_cast<std::size_t>(nthreads));
  std::vector<double> energy(static_cast<std::size_t>(nthreads), 0.0);
  std::vector<Voigt6> virial(static_cast<std::size_t>(nthreads), Voigt6::Zero());
  const bool per_atom = out.per_atom;
  const int* neighbors = accepted ? accepted->neighbors.data() : list.neighbors.data();
  const std::int64_t* first = list.offset.data();
  const std::int64_t* last = accepted ? accepted->end.data() : first + 1;
#pragma omp parallel num_threads(nthreads)
  {
    const int t = omp_get_thread_num();
    const auto ut = static_cast<std::size_t>(t);
    Vec3* f = detail::private_copy(scratch.force, atoms.f, t, Vec3::Zero()).data();
    if (per_atom) {
      double* eatom = detail::private_copy(scratch.scalar, out.energy_atom, t, 0.0).data();
      Voigt6* vatom = detail::private_copy(scratch.virial, out.virial_atom, t, Voigt6::Zero()).data();
      detail::pair_force_range<true>(atoms.x.data(), neighbors, first, last, kernel, range[ut],
                                     range[ut + 1], f, eatom, vatom, energy[ut]);
    } else {
      detail::pair_force_range<false>(atoms.x.data(), neighbors, first, last, kernel, range[ut],
                                      range[ut + 1], f, nullptr, nullptr, energy[ut]);
    }
    virial[ut] = detail::virial_fdotr(atoms.x.data(), f, atoms.size());
#pragma omp barrier
    detail::reduce_copies(scratch.force, atoms.f, nthreads);
    if (per_atom) {
      detail::reduce_copies(scratch.scalar, out.energy_atom, nthreads);
      detail::reduce_copies(scratch.virial, out.virial_atom, nthreads);
    }
  }
  for (int t = 0; t < nthreads; ++t) {
    out.energy += energy[static_cast<std::size_t>(t)];
    out.virial += virial[static_cast<std::size_t>(t)];
  }
}

/// Σ_i per_atom(i) over owned atoms i < n, threaded (static schedule) and summed in thread
/// order: the embedding passes of the many-body potentials. per_atom may write atom i's entries.
template <class F>
double sum_over_atoms(std::size_t n, const F& per_atom) {
  const int nthreads = omp_get_max_threads();
  std::vector<double> partial(static_cast<std::size_t>(nthreads), 0.0);
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel num_threads(nthreads)
  {
    double sum = 0;
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < count; ++i) sum += per_atom(static_cast<std::size_t>(i));
    partial[static_cast<std::size_t>(omp_get_thread_num())] = sum;
  }
  double total = 0;
  for (double e : partial) total += e;
  return total;
}

/// Adds to_i and to_j of `kernel` over the half list into `values` (owned and ghost entries),
/// threads other than the first through `copies`; with `accepted`, records the pairs the kernel
/// accepted (see AcceptedPairs).
template <class T, PairScalarKernel<T> K>
void accumulate_pair_scalars(const Atoms& atoms, const geometry::NeighborList& list,
                             const K& kernel, std::vector<T>& values,
                             std::vector<std::vector<T>>& copies, AcceptedPairs* accepted = nullptr) {
  const int nthreads = omp_get_max_threads();
  const auto range = detail::thread_ranges(list, nthreads);
  copies.resize(static_cast<std::size_t>(nthreads));
  const Vec3* x = atoms.x.data();
  const int* neighbors = list.neighbors.data();
  const std::int64_t* offset = list.offset.data();
  int* kept = nullptr;
  std::int64_t* kept_end = nullptr;
  if (accepted) {
    accepted->neighbors.resize(list.pairs());
    accepted->end.resize(list.nlocal());
    kept = accepted->neighbors.data();
    kept_end = accepted->end.data();
  }
#pragma omp parallel num_threads(nthreads)
  {
    const int t = omp_get_thread_num();
    const K local_kernel = kernel;  // in registers: the stores below could alias a reference
    T* v = detail::private_copy(copies, values, t, T{}).data();
    for (std::size_t i = range[t]; i < range[t + 1]; ++i) {
      const Vec3 xi = x[i];
      T vi{};
      std::int64_t n_kept = offset[i];
      for (auto k = offset[i]; k < offset[i + 1]; ++k) {
        const int j = neighbors[k];
        const Vec3 d = xi - x[j];
        T to_i, to_j;
        if (!local_kernel(static_cast<int>(i), j, d, d.squaredNorm(), to_i, to_j)) continue;
        vi += to_i;
        v[j] += to_j;
        if (kept) kept[n_kept++] = j;
      }
      v[i] += vi;
      if (kept_end) kept_end[i] = n_kept;
    }
#pragma omp barrier
    detail::reduce_copies(copies, values, nthreads);
  }
}

}  // namespace shockfield::md::potentials
