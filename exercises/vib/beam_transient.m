% vib-beam-transient: a moving or sudden force on a Hermite-element beam, Newmark and modes
n = elements; he = L/n; nd = 2*n + 2;
kel = E*I/he^3*[12 6*he -12 6*he; 6*he 4*he^2 -6*he 2*he^2; -12 -6*he 12 -6*he; 6*he 2*he^2 -6*he 4*he^2];
mel = rho*A*he/420*[156 22*he 54 -13*he; 22*he 4*he^2 13*he -3*he^2; 54 13*he 156 -22*he; -13*he -3*he^2 -22*he 4*he^2];
K = zeros(nd); M = K;
for e = 1:n, d = 2*e - 1:2*e + 2; K(d, d) = K(d, d) + kel; M(d, d) = M(d, d) + mel; end
switch bc
  case 'simply-supported', fr = [2:2*n, 2*n + 2];
  case 'cantilever',       fr = 3:2*n + 2;
  otherwise,               fr = 3:2*n;
end
Kf = K(fr, fr); Mf = M(fr, fr); Cf = alpha*Mf + beta*Kf;      % eq. (1)
% the consistent load of P at x: the Hermite shape functions there
N = @(s) [1 - 3*s^2 + 2*s^3, he*(s - 2*s^2 + s^3), 3*s^2 - 2*s^3, he*(s^3 - s^2)];
fx = @(x) full(sparse(2*min(floor(x/he), n - 1) + (1:4), 1, P*N(x/he - min(floor(x/he), n - 1)), nd, 1));
load_at = @(t) strcmp(load, 'moving')*(v*t <= L)*fx(min(v*t, L)) + ...
               ~strcmp(load, 'moving')*(strcmp(load, 'step') || t < t_d)*fx(a*L);
[Phi, D] = eig(Kf, Mf); [w2, o] = sort(diag(D)); Phi = Phi(:, o);
Phi = Phi ./ sqrt(diag(Phi'*Mf*Phi))';
out.omega1 = sqrt(w2(1));
pr = 2*round(probe*n) + 1; ip = find(fr == pr);              % the probe's w among the free DOFs
steps = ceil(t_end/h*(1 - 1e-12)); stride = floor(steps/(points - 1)) + 1;
S = Mf + h/2*Cf + h^2/4*Kf; f = load_at(0); q = zeros(numel(fr), 1); vv = q; acc = Mf \ f(fr); wmax = 0;
for k = 1:steps                                               % Newmark, average acceleration
  qt = q + h*vv + h^2/4*acc; vt = vv + h/2*acc; f = load_at(k*h);
  acc = S \ (f(fr) - Cf*vt - Kf*qt); q = qt + h^2/4*acc; vv = vt + h/2*acc;
  if mod(k, stride) == 0 && ~isempty(ip), wmax = max(wmax, abs(q(ip))); end
end
out.w_max = wmax;
f = fx(a*L); if strcmp(load, 'moving'), f = fx(L/2); end      % the static deflection
u = zeros(nd, 1); u(fr) = Kf \ f(fr); out.w_static = u(pr);
if out.w_static ~= 0, out.dynamic_factor = wmax/abs(out.w_static); end
r = 0;                                                        % eq. (3) at the probe, at the plotted times
for k = 0:stride:steps
  f = load_at(k*h); f = f(fr); z = Kf \ f - Phi(:, 1:modes)*((Phi(:, 1:modes)'*f)./w2(1:modes));
  if ~isempty(ip), r = max(r, abs(z(ip))); end
end
out.static_residual = r;
