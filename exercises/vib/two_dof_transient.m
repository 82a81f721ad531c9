% vib-2dof-transient: modal superposition (exact) against Newmark (direct)
M = [m1 0; 0 m2]; K = [k1 + k2, -k2; -k2, k2 + k3];
F = [F1; F2]; x0 = [x1_0; x2_0]; v0 = [v1_0; v2_0];
[Phi, L] = eig(K, M); [w2, o] = sort(max(diag(L), 0)); Phi = Phi(:, o);
Phi = Phi ./ sqrt(diag(Phi'*M*Phi))';                        % phi' M phi = 1
w = sqrt(w2); c = 2*zeta*w;                                   % modal damping
C = M*Phi*diag(c)*Phi'*M;                                     % eq. (1)
out.omega1 = w(1); out.omega2 = w(2);
pe = @(wh) wh/(2*atan(wh/2)) - 1;                             % eq. (3)
out.period_error_1 = 0; if w(1) > 0, out.period_error_1 = pe(w(1)*h); end
out.period_error_2 = pe(w(2)*h);
N = ceil(t_end/h*(1 - 1e-12)); t = (0:N)*h;
% direct: Newmark average acceleration on the coupled equations
S = M + h/2*C + h^2/4*K; q = x0; v = v0; a = M \ (F - C*v - K*q); Q = zeros(2, N + 1); Q(:, 1) = q;
for k = 1:N
  qt = q + h*v + h^2/4*a; vt = v + h/2*a;
  a = S \ (F*cos(omega*t(k + 1)) - C*vt - K*qt);
  q = qt + h^2/4*a; v = vt + h/2*a; Q(:, k + 1) = q;
end
% exact: each mode a damped oscillator (eq. 2), by the transition matrix of its state
X = zeros(2, N + 1); Xm = X;
for j = 1:2
  p = Phi(:, j)'*F; e = [Phi(:, j)'*M*x0; Phi(:, j)'*M*v0; 1; 0];
  G = [0 1 0 0; -w2(j) -c(j) p 0; 0 0 0 -omega; 0 0 omega 0];
  P = expm(G*h); eta = zeros(1, N + 1);
  for k = 1:N + 1, eta(k) = e(1); e = P*e; end
  X = X + Phi(:, j)*eta;
  if j <= modes, Xm = Xm + Phi(:, j)*eta; end
end
s = ceil(N/(points - 1)); idx = unique([1:s:N + 1, N + 1]);     % the plotted steps
d = Q(:, idx) - X(:, idx); out.max_error = max(abs(d(:)));
d = Xm(:, idx) - X(:, idx); out.truncation_error = max(abs(d(:)));
