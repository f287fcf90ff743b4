// The MPI module libdrt_mpi.so (distributed/mpi_module.h): each entry is one
// MPI call (or a probe and its receive) on MPI_COMM_WORLD.
#include "distributed/mpi_module.h"

#include <mpi.h>

namespace drt::mpi_module {

namespace {

std::string start(int& rank, int& size) {
    int provided = 0;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
        return "MPI_Init_thread failed";
    if (provided < MPI_THREAD_FUNNELED) {
        MPI_Finalize();
        return "this MPI library cannot be used with threads (MPI_THREAD_FUNNELED)";
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return "";
}

void finish() { MPI_Finalize(); }

int largest(int value) {
    int worst = value;
    MPI_Allreduce(&value, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return worst;
}

void broadcast(void* data, int bytes) { MPI_Bcast(data, bytes, MPI_BYTE, 0, MPI_COMM_WORLD); }

void abort(int status) { MPI_Abort(MPI_COMM_WORLD, status); }

void* send(const void* data, int bytes, int to, int tag) {
    auto* request = new MPI_Request(MPI_REQUEST_NULL);
    MPI_Isend(data, bytes, MPI_BYTE, to, tag, MPI_COMM_WORLD, request);
    return request;
}

bool sent(void* handle) {
    auto* request = static_cast<MPI_Request*>(handle);
    int done = 0;
    MPI_Test(request, &done, MPI_STATUS_IGNORE);
    if (done) delete request;
    return done != 0;
}

bool receive(int source, std::vector<std::byte>& bytes, int& from, int& tag) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(source == kAnyRank ? MPI_ANY_SOURCE : source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (!flag) return false;
    int size = 0;
    MPI_Get_count(&status, MPI_BYTE, &size);
    bytes.resize(size_t(size));
    MPI_Recv(bytes.data(), size, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    from = status.MPI_SOURCE;
    tag = status.MPI_TAG;
    return true;
}

} // namespace

} // namespace drt::mpi_module

extern "C" const drt::MpiModule* drt_mpi_module() {
    using namespace drt::mpi_module;
    static const drt::MpiModule module = {drt::kMpiModuleVersion, &start, &finish, &largest, &broadcast,
                                          &abort, &send, &sent, &receive};
    return &module;
}
