% vib-ndof-transient: a Rayleigh-damped chain, m modes against all, and Newmark
e = ones(n, 1); K = k*(2*diag(e) - diag(e(1:n-1), 1) - diag(e(1:n-1), -1));
if strcmp(ends, 'fixed-free'), K(n, n) = k; end
M = m*eye(n); C = alpha*M + beta*K;                       % eq. (1)
Fv = zeros(n, 1); Fv(p) = F;
[Phi, L] = eig(K, M); [w2, o] = sort(diag(L)); Phi = Phi(:, o);
Phi = Phi ./ sqrt(diag(Phi'*M*Phi))'; w = sqrt(w2);
c = alpha + beta*w2;                                      % eq. (2): 2 zeta_j omega_j
out.omega1 = 2*sqrt(k/m)*sin(pi/(2*(n + 1)));
if strcmp(ends, 'fixed-free'), out.omega1 = 2*sqrt(k/m)*sin(pi/(2*(2*n + 1))); end
N = ceil(t_end/h*(1 - 1e-12)); t = (0:N)*h;
S = M + h/2*C + h^2/4*K; q = zeros(n, 1); v = q; a = M \ Fv; Q = zeros(n, N + 1);
for k = 1:N                                               % Newmark, average acceleration
  qt = q + h*v + h^2/4*a; vt = v + h/2*a;
  a = S \ (Fv*cos(omega*t(k + 1)) - C*vt - K*qt);
  q = qt + h^2/4*a; v = vt + h/2*a; Q(:, k + 1) = q;
end
X = zeros(n, N + 1); Xm = X;                              % each mode exact (its transition matrix)
for j = 1:n
  pj = Phi(:, j)'*Fv; s = [0; 0; 1; 0];
  P = expm([0 1 0 0; -w2(j) -c(j) pj 0; 0 0 0 -omega; 0 0 omega 0]*h); eta = zeros(1, N + 1);
  for kk = 1:N + 1, eta(kk) = s(1); s = P*s; end
  X = X + Phi(:, j)*eta;
  if j <= modes, Xm = Xm + Phi(:, j)*eta; end
end
st = ceil(N/(points - 1)); idx = unique([1:st:N + 1, N + 1]);
d = Q(:, idx) - X(:, idx); out.max_error = max(abs(d(:)));
d = Xm(:, idx) - X(:, idx); out.truncation_error = max(abs(d(:)));
r = K \ Fv - Phi(:, 1:modes)*((Phi(:, 1:modes)'*Fv)./w2(1:modes));   % eq. (3)
out.static_residual = max(abs(r));
