#include "Partition.hpp"

#include <zoltan.h>

#include <stdexcept>

#include "parallel/CommunicatorImpl.hpp"

namespace pf {
namespace {

// Zoltan sees only this rank's slab of the cloud; RCB then moves points between ranks.
int numObjects(void* data, int* ierr) {
  *ierr = ZOLTAN_OK;
  return static_cast<const PointCloud*>(data)->size();
}

void objectList(void* data, int, int, ZOLTAN_ID_PTR gids, ZOLTAN_ID_PTR lids, int, float*, int* ierr) {
  const PointCloud* s = static_cast<const PointCloud*>(data);
  for (int i = 0; i < s->size(); ++i) {
    gids[i] = static_cast<ZOLTAN_ID_TYPE>(s->gid[i]);
    lids[i] = static_cast<ZOLTAN_ID_TYPE>(i);
  }
  *ierr = ZOLTAN_OK;
}

int numGeometry(void*, int* ierr) {
  *ierr = ZOLTAN_OK;
  return 3;
}

void geometry(void* data, int, int, int num, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR lids, int dim, double* out, int* ierr) {
  const PointCloud* s = static_cast<const PointCloud*>(data);
  for (int i = 0; i < num; ++i)
    for (int d = 0; d < dim; ++d) out[i * dim + d] = s->x[3 * lids[i] + d];
  *ierr = ZOLTAN_OK;
}

}  // namespace

std::vector<int> partitionRcb(const PointCloud& slab, const Communicator& communicator) {
  const MPI_Comm comm = communicator.impl().mpi;
  const int rank = communicator.rank(), size = communicator.size();
  std::vector<int> owner(slab.size(), rank);
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
  void* data = const_cast<PointCloud*>(&slab);
  Zoltan_Set_Num_Obj_Fn(zz, numObjects, data);
  Zoltan_Set_Obj_List_Fn(zz, objectList, data);
  Zoltan_Set_Num_Geom_Fn(zz, numGeometry, data);
  Zoltan_Set_Geom_Multi_Fn(zz, geometry, data);

  int changes = 0, ngid = 0, nlid = 0, nimp = 0, nexp = 0;
  ZOLTAN_ID_PTR impG = nullptr, impL = nullptr, expG = nullptr, expL = nullptr;
  int *impP = nullptr, *impPart = nullptr, *expP = nullptr, *expPart = nullptr;
  const int rc = Zoltan_LB_Partition(zz, &changes, &ngid, &nlid, &nimp, &impG, &impL, &impP, &impPart, &nexp,
                                     &expG, &expL, &expP, &expPart);
  if (rc != ZOLTAN_OK) {
    Zoltan_Destroy(&zz);
    throw std::runtime_error("Zoltan RCB partitioning failed");
  }
  for (int e = 0; e < nexp; ++e) owner[expL[e]] = expPart[e];
  Zoltan_LB_Free_Part(&impG, &impL, &impP, &impPart);
  Zoltan_LB_Free_Part(&expG, &expL, &expP, &expPart);
  Zoltan_Destroy(&zz);
  return owner;
}

}  // namespace pf
