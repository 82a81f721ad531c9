% vib-beam-transient: a moving or sudden force on a Hermite-element beam, Newmark and modes
n = elements; he = L/n; nd = 2*n + 2;
kel = E*I/he^3*[12 6*he -12 6*he; 6*he 4*he^2 -6*he 2*he^2; -12 -6*he 12 -6*he; 6*he 2*he^2 -6*he 4*he^2];
mel = rho*A*he/420*[156 22*he 54 -13*he; 22*he 4*he^2 13*he -3*he^2; 54 13*he 156 -22*he; -13*he -3*he^2 -22*he 4*he^2];
ii = []; jj = []; kk = []; mm = [];                           % sparse assembly: band matrices
for e = 1:n
  d = 2*e - 1:2*e + 2; [J, I2] = meshgrid(d, d);
  ii = [ii; I2(:)]; jj = [jj; J(:)]; kk = [kk; kel(:)]; mm = [mm; mel(:)];
end
K = sparse(ii, jj, kk, nd, nd); M = sparse(ii, jj, mm, nd, nd);
switch bc
  case 'simply-supported', fr = [2:2*n, 2*n + 2];
  case 'cantilever',       fr = 3:2*n + 2;
  otherwise,               fr = 3:2*n;
end
Kf = K(fr, fr); Mf = M(fr, fr); Cf = alpha*Mf + beta*Kf; nf = numel(fr);   % eq. (1)
% the consistent load of P at x: the Hermite shape functions there
Nc = [1 0 -3 2; 0 he -2*he he; 0 0 3 -2; 0 0 -he he];        % coefficients of 1, s, s^2, s^3
fx = @(x) full(sparse(2*min(floor(x/he), n - 1) + (1:4), 1, P*Nc*(x/he - min(floor(x/he), n - 1)).^(0:3)', nd, 1));
load_at = @(t) strcmp(load, 'moving')*(v*t <= L)*fx(min(v*t, L)) + ...
               ~strcmp(load, 'moving')*(strcmp(load, 'step') || t < t_d)*fx(a*L);
ff = @(X) X(fr, :);                                           % the rows of the free DOFs
% the strain energy from the element curvatures at both ends (q'Kq would lose digits)
k0 = @(u) (6*(u(3:2:end) - u(1:2:end - 2))/he - 4*u(2:2:end - 2) - 2*u(4:2:end))/he;
k1 = @(u) (-6*(u(3:2:end) - u(1:2:end - 2))/he + 2*u(2:2:end - 2) + 4*u(4:2:end))/he;
U = @(u) E*I*he/6*sum(k0(u).^2 + k0(u).*k1(u) + k1(u).^2);
if nf <= 100, nm = nf; else, nm = modes; end                  % every mode where there are few
[Phi, D] = eig(full(Kf), full(Mf)); [w2, o] = sort(diag(D)); Phi = Phi(:, o(1:nm)); w2 = w2(1:nm);
Phi = Phi ./ sqrt(diag(Phi'*Mf*Phi))';
out.omega1 = sqrt(w2(1));
pp = double(fr == 2*round(probe*n) + 1);                      % picks the probe's w
steps = ceil(t_end/h*(1 - 1e-12)); stride = floor(steps/(points - 1)) + 1; T = (0:stride:steps)*h;
% Newmark, average acceleration, on every DOF, S factored once; the energy
% identity E~ - E~0 = W - D with W, D by the trapezoidal rule in q
R = chol(Mf + h/2*Cf + h^2/4*Kf); f = ff(load_at(0)); q = zeros(nf, 1); vv = q; acc = Mf \ f;
wd = zeros(size(T)); u = zeros(nd, 1); W = 0; Dd = 0; bal = 0; big = 0; cv = q;
for k = 1:steps
  qt = q + h*vv + h^2/4*acc; vt = vv + h/2*acc; f1 = ff(load_at(k*h));
  acc = R \ (R' \ (f1 - Cf*vt - Kf*qt)); q1 = qt + h^2/4*acc; vv = vt + h/2*acc; cv1 = Cf*vv;
  W = W + (q1 - q)'*(f + f1)/2; Dd = Dd + (q1 - q)'*(cv + cv1)/2; q = q1; f = f1; cv = cv1;
  if mod(k, stride) == 0 || k == steps
    u(fr) = q; Ek = vv'*Mf*vv/2; Eu = U(u);
    bal = max(bal, abs(Ek + Eu - W + Dd)); big = max([big, Ek, Eu, abs(W), abs(Dd)]);
  end
  if mod(k, stride) == 0, wd(k/stride + 1) = pp*q; end
end
out.w_max = max(abs(wd)); out.energy_identity = bal/max(big, realmin);
if nf <= 100
  % eq. (2) for every mode, exact in time: the state (eta, eta', p) with p the
  % load's polynomial state (1, s, s^2, s^3), s = (v t - x_e)/he, advanced by expm
  c = alpha + beta*w2; Gz = [zeros(nm), eye(nm); -diag(w2), -diag(c)];
  G = @(B, Dp) [Gz, [zeros(nm, size(B, 2)); Phi'*B]; zeros(size(Dp, 1), 2*nm), Dp];
  if strcmp(load, 'moving')                                   % on element e: its 4 DOFs
    Be = @(e) ff(full(sparse(2*e + (1:4), 1:4, 1, nd, 4)))*P*Nc;
    Dp = [0 0 0 0; 1 0 0 0; 0 2 0 0; 0 0 3 0]*v/he; Gc = G(Be(0), Dp); ev = (1:n)*he/v; p0 = [1; 0; 0; 0];
  else
    Gc = G(ff(fx(a*L)), 0); ev = t_d; p0 = 1;
    if strcmp(load, 'step'), ev = []; end
  end
  z = [zeros(2*nm, 1); p0]; t = 0; ie = 1; Eh = expm(Gc*(T(2) - T(1))); wa = zeros(size(T)); wm = wa;
  for i = 2:numel(T)
    while ie <= numel(ev) && ev(ie) <= T(i)                   % the load enters an element, or stops
      z = expm(Gc*(ev(ie) - t))*z; t = ev(ie); ie = ie + 1; z(2*nm + 1:end) = 0;
      if strcmp(load, 'moving') && ie <= n, Gc = G(Be(ie - 1), Dp); z(2*nm + 1) = 1; end
      Eh = expm(Gc*(T(2) - T(1)));
    end
    if t == T(i - 1), z = Eh*z; else, z = expm(Gc*(T(i) - t))*z; end
    t = T(i); wa(i) = pp*Phi*z(1:nm); wm(i) = pp*Phi(:, 1:modes)*z(1:modes);
  end
  out.truncation_error = max(abs(wm - wa)); out.time_error = max(abs(wd - wa));
end
f = fx(a*L); if strcmp(load, 'moving'), f = fx(L/2); end      % the static deflection
u = zeros(nd, 1); u(fr) = Kf \ f(fr); out.w_static = u(2*round(probe*n) + 1);
if out.w_static ~= 0, out.dynamic_factor = out.w_max/abs(out.w_static); end
r = 0;                                                        % eq. (3) at the probe, at the plotted times
for k = 0:stride:steps
  f = ff(load_at(k*h)); z = Kf \ f - Phi(:, 1:modes)*((Phi(:, 1:modes)'*f)./w2(1:modes));
  r = max(r, abs(pp*z));
end
out.static_residual = r;
