#include "Partition.hpp"

#include <zoltan.h>

#include <stdexcept>

#include "parallel/CommunicatorImpl.hpp"

namespace pf {
namespace {

// Zoltan sees only this rank's initial slice of the cloud; RCB then moves points between ranks.
struct Slice {
  const std::vector<double>* coords;
  int first, count;
};

int numObjects(void* data, int* ierr) {
  *ierr = ZOLTAN_OK;
  return static_cast<Slice*>(data)->count;
}

void objectList(void* data, int, int, ZOLTAN_ID_PTR gids, ZOLTAN_ID_PTR lids, int, float*, int* ierr) {
  const Slice* s = static_cast<Slice*>(data);
  for (int i = 0; i < s->count; ++i) {
    gids[i] = static_cast<ZOLTAN_ID_TYPE>(s->first + i);
    lids[i] = static_cast<ZOLTAN_ID_TYPE>(i);
  }
  *ierr = ZOLTAN_OK;
}

int numGeometry(void*, int* ierr) {
  *ierr = ZOLTAN_OK;
  return 3;
}

void geometry(void* data, int, int, int num, ZOLTAN_ID_PTR gids, ZOLTAN_ID_PTR, int dim, double* out, int* ierr) {
  const Slice* s = static_cast<Slice*>(data);
  for (int i = 0; i < num; ++i)
    for (int d = 0; d < dim; ++d) out[i * dim + d] = (*s->coords)[3 * gids[i] + d];
  *ierr = ZOLTAN_OK;
}

}  // namespace

std::vector<int> partitionRcb(const std::vector<double>& coords, const Communicator& communicator) {
  const MPI_Comm comm = communicator.impl().mpi;
  const int rank = communicator.rank(), size = communicator.size();
  const int n = static_cast<int>(coords.size() / 3);
  std::vector<int> owner(n, 0);
  if (size == 1) return owner;

  float version = 0;
  Zoltan_Initialize(0, nullptr, &version);
  Zoltan_Struct* zz = Zoltan_Create(comm);
  Zoltan_Set_Param(zz, "DEBUG_LEVEL", "0");
  Zoltan_Set_Param(zz, "LB_METHOD", "RCB");
  Zoltan_Set_Param(zz, "NUM_GID_ENTRIES", "1");
  Zoltan_Set_Param(zz, "NUM_LID_ENTRIES", "1");
  Zoltan_Set_Param(zz, "RETURN_LISTS", "EXPORT");
  Zoltan_Set_Param(zz, "RCB_OUTPUT_LEVEL", "0");
  Zoltan_Set_Param(zz, "KEEP_CUTS", "0");

  Slice slice{&coords, static_cast<int>(static_cast<long long>(n) * rank / size), 0};
  slice.count = static_cast<int>(static_cast<long long>(n) * (rank + 1) / size) - slice.first;
  Zoltan_Set_Num_Obj_Fn(zz, numObjects, &slice);
  Zoltan_Set_Obj_List_Fn(zz, objectList, &slice);
  Zoltan_Set_Num_Geom_Fn(zz, numGeometry, &slice);
  Zoltan_Set_Geom_Multi_Fn(zz, geometry, &slice);

  int changes = 0, ngid = 0, nlid = 0, nimp = 0, nexp = 0;
  ZOLTAN_ID_PTR impG = nullptr, impL = nullptr, expG = nullptr, expL = nullptr;
  int *impP = nullptr, *impPart = nullptr, *expP = nullptr, *expPart = nullptr;
  const int rc = Zoltan_LB_Partition(zz, &changes, &ngid, &nlid, &nimp, &impG, &impL, &impP, &impPart, &nexp,
                                     &expG, &expL, &expP, &expPart);
  if (rc != ZOLTAN_OK) {
    Zoltan_Destroy(&zz);
    throw std::runtime_error("Zoltan RCB partitioning failed");
  }
  // Start from the initial slices, apply this rank's exports, then combine: each point is set by exactly
  // one rank (the one whose slice held it), so a MAX reduction over -1-initialised entries is exact.
  std::vector<int> local(n, -1);
  for (int i = 0; i < slice.count; ++i) local[slice.first + i] = rank;
  for (int e = 0; e < nexp; ++e) local[expG[e]] = expPart[e];
  MPI_Allreduce(local.data(), owner.data(), n, MPI_INT, MPI_MAX, comm);
  Zoltan_LB_Free_Part(&impG, &impL, &impP, &impPart);
  Zoltan_LB_Free_Part(&expG, &expL, &expP, &expPart);
  Zoltan_Destroy(&zz);
  return owner;
}

}  // namespace pf
