#pragma once
// The routes of the lighting-design server (docs/serve.md, "API").

#include <mutex>

// Eigen first: httplib pulls in <resolv.h>, whose `_res` macro breaks Eigen's headers.
#include "penumbra/serve/lighting_session.h"

#include <httplib.h>

namespace penumbra::serve {

// registers the API and the page's files on server. Every handler locks mutex around
// its use of session.
void register_routes(httplib::Server& server, LightingSession& session, std::mutex& mutex);

}  // namespace penumbra::serve
