-- wrk script for `make loadtest`: cycle through the requests in the file
-- named by MM_PATHS (a path to GET, or "POST path json" a line), each
-- thread from its own offset; count statuses; print the percentiles.
-- The requests are made here, before wrk has set its Host header: each gets
-- its own (nginx in front refuses a request without one).
local reqs = {}
local json = { ["Content-Type"] = "application/json", ["Host"] = "127.0.0.1" }
local plain = { ["Host"] = "127.0.0.1" }
for line in io.lines(os.getenv("MM_PATHS")) do
  local path, body = line:match("^POST (%S+) (.*)$")
  if path then
    reqs[#reqs + 1] = wrk.format("POST", path, json, body)
  else
    reqs[#reqs + 1] = wrk.format("GET", line, plain)
  end
end

local threads = {}
function setup(thread)
  thread:set("offset", #threads * 7)
  table.insert(threads, thread)
end

function init(args)
  i = offset
  s2xx, s4xx, s5xx = 0, 0, 0
end

function request()
  i = i + 1
  return reqs[(i % #reqs) + 1]
end

function response(status, headers, body)
  if status >= 500 then s5xx = s5xx + 1
  elseif status >= 400 then s4xx = s4xx + 1
  else s2xx = s2xx + 1 end
end

function done(summary, latency, requests)
  local a, b, c = 0, 0, 0
  for _, t in ipairs(threads) do
    a = a + t:get("s2xx"); b = b + t:get("s4xx"); c = c + t:get("s5xx")
  end
  io.write(string.format("statuses: %d 2xx, %d 4xx, %d 5xx\n", a, b, c))
  io.write(string.format("socket errors: connect %d, read %d, write %d, timeout %d\n",
    summary.errors.connect, summary.errors.read, summary.errors.write, summary.errors.timeout))
  for _, p in ipairs({50, 90, 99, 99.9}) do
    io.write(string.format("latency p%g: %.2f ms\n", p, latency:percentile(p) / 1000))
  end
end
