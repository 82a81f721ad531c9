% vib-bar-modes: linear bar elements, consistent or lumped mass, against n pi c / L
c = sqrt(E/rho);
% uniform mesh of n elements, length h: stiffness and the two mass matrices, eq. (2)
Kb = @(n, h) E*A/h*(diag([1, 2*ones(1, n - 1), 1]) - diag(ones(1, n), 1) - diag(ones(1, n), -1));
Mc = @(n, h) rho*A*h/6*(diag([2, 4*ones(1, n - 1), 2]) + diag(ones(1, n), 1) + diag(ones(1, n), -1));
Ml = @(n, h) rho*A*h/2*diag([1, 2*ones(1, n - 1), 1]);
switch bc                                      % the free nodes
  case 'fixed-free',  fr = @(n) 2:n + 1;
  case 'fixed-fixed', fr = @(n) 2:n;
  otherwise,          fr = @(n) 1:n + 1;
end
j = (1:modes)';                                % exact frequencies, eq. (1)
if strcmp(bc, 'fixed-free'), wx = (2*j - 1)*pi*c/(2*L); else, wx = j*pi*c/L; end
% the mesh asked for: eq. (3), (K - omega^2 M) phi = 0 on the free nodes
n = elements; f = fr(n);
if strcmp(mass, 'lumped'), Mm = Ml(n, L/n); else, Mm = Mc(n, L/n); end
Kn = Kb(n, L/n); lam = sort(eig(Kn(f, f), Mm(f, f)));
out.rigid_modes = sum(lam < 1e-9*lam(end));    % free-free: one with omega = 0
w = sqrt(lam(out.rigid_modes + 1:end));
out.omega1 = w(1); out.omega1_exact = wx(1);
% convergence of omega1, 4 ... 128 elements, eq. (6): the fitted slope
ns = [4 8 16 32 64 128]; e = zeros(2, 6);
for i = 1:6
  n = ns(i); f = fr(n); Kn = Kb(n, L/n); Mcn = Mc(n, L/n); Mln = Ml(n, L/n);
  lc = sort(eig(Kn(f, f), Mcn(f, f))); ll = sort(eig(Kn(f, f), Mln(f, f)));
  r = strcmp(bc, 'free-free');
  e(:, i) = abs(sqrt([lc(r + 1); ll(r + 1)])/wx(1) - 1);
end
pc = polyfit(log(L./ns), log(e(1, :)), 1); pl = polyfit(log(L./ns), log(e(2, :)), 1);
out.slope_consistent = pc(1); out.slope_lumped = pl(1);
