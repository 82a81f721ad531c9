% vib-bar-wave: a step force at the free end of a fixed bar, finite elements in space and time
c = sqrt(E/rho); T = L/c; n = elements; he = L/n; h = courant*he/c;
out.c = c; out.transit_time = T; out.h = h; out.u_end_max_exact = 2*F*L/(E*A);
K = E*A/he*(diag([1, 2*ones(1, n - 1), 1]) - diag(ones(1, n), 1) - diag(ones(1, n), -1));
Ml = rho*A*he/2*diag([1, 2*ones(1, n - 1), 1]);
Mc = rho*A*he/6*(diag([2, 4*ones(1, n - 1), 2]) + diag(ones(1, n), 1) + diag(ones(1, n), -1));
f = 2:n + 1; K = K(f, f); Ml = Ml(f, f); Mc = Mc(f, f);     % u = 0 at x = 0
lim = [2/(sqrt(max(eig(K, Ml)))*he/c), 2/(sqrt(max(eig(K, Mc)))*he/c)];   % eq. (3), exact for the mesh
out.courant_limit_lumped = lim(1); out.courant_limit_consistent = lim(2);
steps = ceil(transits*T/h*(1 - 1e-12)); stride = floor(steps/150) + 1;
trip = round(2*n/courant);                                   % a round trip in whole steps: stored
if abs(2*n/courant - trip) < 1e-9*trip, while mod(trip, stride) ~= 0, stride = stride - 1; end, end
fv = zeros(n, 1); fv(n) = F;                                 % the end force
explicit = strcmp(method, 'central-difference');
for model = 1:2                                              % lumped first, then consistent
  if explicit && courant >= lim(model), continue; end        % unstable: not run
  if model == 1, M = Ml; else, M = Mc; end
  be = 1/4; if explicit, be = 0; end
  S = M + be*h^2*K; q = zeros(n, 1); v = q; a = M \ fv; umax = 0;
  for k = 1:steps
    qt = q + h*v + h^2*(1/2 - be)*a; vt = v + h/2*a;
    a = S \ (fv - K*qt); q = qt + be*h^2*a; v = vt + h/2*a;
    if mod(k, stride) == 0, umax = max(umax, abs(q(n))); end
  end
  out.u_end_max = sign(F)*umax;
  break
end
