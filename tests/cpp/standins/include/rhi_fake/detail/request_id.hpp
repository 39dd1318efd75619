// rhi-gen test stand-in internals: the fake's service request id. The client's id goes into the
// first bytes of rmw_request_id_t::writer_guid (the rest zero), so a response -- also one a deferred
// service callback sends later -- finds its way back to the client.
#pragma once

#include <cstdint>
#include <cstring>

#include "rmw/types.h"

namespace rhi_fake {
namespace detail {

inline void write_request_id(
  rmw_request_id_t & id, std::uint64_t client_id, std::int64_t sequence_number)
{
  static_assert(sizeof(client_id) <= RMW_GID_STORAGE_SIZE, "writer_guid holds the client id");
  std::memset(id.writer_guid, 0, sizeof(id.writer_guid));
  std::memcpy(id.writer_guid, &client_id, sizeof(client_id));
  id.sequence_number = sequence_number;
}

inline std::uint64_t client_id_of(const rmw_request_id_t & id)
{
  std::uint64_t client_id = 0;
  std::memcpy(&client_id, id.writer_guid, sizeof(client_id));
  return client_id;
}

}  // namespace detail
}  // namespace rhi_fake
