% Potential energy, its derivatives, eqs. (1)-(3).
V = @(t) 0.5 * k * a^2 * sin(t).^2 + W * L * cos(t);
dV = @(t) sin(t) .* (k * a^2 * cos(t) - W * L);
d2V = @(t) k * a^2 * cos(2 * t) - W * L * cos(t);
out.W_cr = k * a^2 / L;                             % eq. (4)
if out.W_cr > 0, out.W_ratio = W / out.W_cr; end
c = W * L / (k * a^2);
if c < 1, out.theta_eq = acos(c); end
% equilibria: roots of dV over one turn (subdivide, bracket, refine)
t = linspace(-pi + 0.1, pi + 0.1, 721);
f = dV(t);
eqs = [];
for i = 1:720
  if f(i) * f(i + 1) < 0
    eqs(end + 1) = fzero(dV, [t(i) t(i + 1)]);
  end
end
eqs(eqs > pi) = eqs(eqs > pi) - 2 * pi;
out.n_equilibria = numel(eqs);
names = {'unstable', 'neutral', 'stable'};
out.upright = 0;
for q = eqs
  s = sign(d2V(q));
  if abs(d2V(q)) <= 1e-9 * (k * a^2 + W * L), s = 0; end
  fprintf('theta = %.15g rad: V = %.10g J, V'''' = %.10g J: %s\n', q, V(q), d2V(q), names{s + 2});
  if abs(q) < 1e-6, out.upright = s; end
end
