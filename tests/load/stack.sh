# tests/load/stack.sh — sourced by failover.sh and class_start.sh: the
# deployment of README's "nginx + N instances" on 127.0.0.1, in a temporary
# folder, every port chosen free by the OS.
#   stack_install                make install DESTDIR=$work PREFIX=/usr
#   stack_instance VAR_PID VAR_PORT [args]   an installed instance on a free port
#   stack_nginx PORT1 PORT2...   nginx with deploy/nginx/mechmat.conf, its
#                                ports and paths replaced; sets nginx_port
#   stack_stop                   everything started, stopped
# Needs: $work (a temporary folder), $BUILD.

stack_pids=()

stack_install() {
  make --no-print-directory install DESTDIR="$work/root" PREFIX=/usr BUILD="$BUILD" > "$work/install.log" 2>&1 \
    || { cat "$work/install.log"; echo "stack: make install failed"; return 1; }
  share="$work/root/usr/share/mechmat"
  server_bin="$work/root/usr/bin/mechmat-server"
}

# a free port, chosen by the OS (bound, read, released)
free_port() {
  "$BUILD/load/loadtool" freeport
}

stack_instance() {
  local -n pid_var=$1 port_var=$2
  shift 2
  local out="$work/instance-$RANDOM.out"
  # setsid: each instance in a session of its own, as a service is (systemd
  # gives each its own cgroup), not in the load generator's: with the
  # kernel's autogroups a shared session shares one CPU slice against
  # every other session of the machine, which no deployment does
  setsid "$server_bin" --host 127.0.0.1 --port 0 --quiet "$@" > "$out" 2>&1 &
  pid_var=$!
  stack_pids+=("$pid_var")
  for _ in $(seq 200); do grep -q listening "$out" && break; sleep 0.05; done
  port_var=$(sed -n 's/.*127\.0\.0\.1:\([0-9]*\).*/\1/p' "$out" | head -1)
  [[ -n "$port_var" ]] || { cat "$out"; echo "stack: an instance did not start"; return 1; }
}

stack_nginx() {
  nginx_port=$(free_port)
  mkdir -p "$work/nginx/logs" "$work/nginx/cache" "$work/nginx/tmp"
  local upstreams="" p
  for p in "$@"; do
    upstreams+="    server 127.0.0.1:$p max_fails=1 fail_timeout=10s;\n"
  done
  # the deployed file, its instances, port and paths replaced
  sed -e '/^    server 127\.0\.0\.1:808[12] /d' \
      -e "s|^    keepalive 64;|${upstreams}    keepalive 64;|" \
      -e "s|listen 80;|listen 127.0.0.1:$nginx_port;|" \
      -e "s|/usr/local/share/mechmat|$share|g" \
      -e "s|/var/cache/nginx/mechmat|$work/nginx/cache|" \
      deploy/nginx/mechmat.conf > "$work/nginx/mechmat.conf"
  cat > "$work/nginx/nginx.conf" <<CONF
$( [[ $(id -u) -eq 0 ]] && echo "user root;" )
worker_processes 2;
pid $work/nginx/nginx.pid;
error_log $work/nginx/logs/error.log warn;
events { worker_connections 8192; }
worker_rlimit_nofile 20000;
http {
    include /etc/nginx/mime.types;
    default_type application/octet-stream;
    access_log off;
    sendfile on;
    tcp_nopush on;
    keepalive_requests 100000;
    client_body_temp_path $work/nginx/tmp/body;
    proxy_temp_path $work/nginx/tmp/proxy;
    fastcgi_temp_path $work/nginx/tmp/fastcgi;
    uwsgi_temp_path $work/nginx/tmp/uwsgi;
    scgi_temp_path $work/nginx/tmp/scgi;
    include $work/nginx/mechmat.conf;
}
CONF
  nginx -t -p "$work/nginx" -c "$work/nginx/nginx.conf" > "$work/nginx/test.log" 2>&1 \
    || { cat "$work/nginx/test.log"; echo "stack: nginx refuses the configuration"; return 1; }
  setsid nginx -p "$work/nginx" -c "$work/nginx/nginx.conf" -g 'daemon off;' > "$work/nginx/out.log" 2>&1 &
  nginx_pid=$!
  stack_pids+=("$nginx_pid")
  for _ in $(seq 200); do curl -s -o /dev/null "http://127.0.0.1:$nginx_port/api/health" && break; sleep 0.05; done
  curl -s -o /dev/null "http://127.0.0.1:$nginx_port/api/health" || { echo "stack: nginx does not answer"; return 1; }
}

stack_stop() {
  local p
  for p in "${stack_pids[@]}"; do kill "$p" 2>/dev/null; done
  for p in "${stack_pids[@]}"; do wait "$p" 2>/dev/null; done
  stack_pids=()
}
