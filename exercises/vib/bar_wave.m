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
explicit = strcmp(method, 'central-difference'); be = 1/4*~explicit; Ks = sparse(K);
names = {'energy_identity_lumped', 'energy_identity_consistent'};
for model = 1:2                                              % lumped, then consistent
  if explicit && courant >= lim(model), continue; end        % unstable: not run
  if model == 1, M = sparse(Ml); else, M = sparse(Mc); end
  R = chol(M + be*h^2*Ks); q = zeros(n, 1); v = q; a = M \ fv; umax = 0;
  % the scheme's energy identity E~ - E~0 = W, E~ = T + U - h^2/2 (1/4 - beta) a'Ma,
  % U from the element strains, W = sum dq' F (the trapezoidal rule in q)
  E0 = -h^2/2*(1/4 - be)*(a'*M*a); W = 0; bal = 0; big = 0;
  for k = 1:steps
    qt = q + h*v + h^2*(1/2 - be)*a; vt = v + h/2*a;
    a = R \ (R' \ (fv - Ks*qt)); q1 = qt + be*h^2*a; v = vt + h/2*a;
    W = W + (q1 - q)'*fv; q = q1;
    if mod(k, stride) == 0 || k == steps
      T2 = v'*M*v/2; U = E*A/(2*he)*sum(diff([0; q]).^2);
      bal = max(bal, abs(T2 + U - h^2/2*(1/4 - be)*(a'*M*a) - E0 - W)); big = max([big, T2, U, abs(W)]);
    end
    if mod(k, stride) == 0, umax = max(umax, abs(q(n))); end
  end
  out.(names{model}) = bal/big;
  if ~isfield(out, 'u_end_max'), out.u_end_max = sign(F)*umax; end
end
