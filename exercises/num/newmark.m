% num-newmark: M q'' + C q' + K q = F cos(omega t) - knl q1^3 e1, step by step
F = F(:); q0 = q0(:); v0 = v0(:); n = size(M, 1);
switch method                                    % beta, gamma, alpha_f of (3)-(4)
  case 'average-acceleration', be = 1/4; ga = 1/2; af = 0;
  case 'linear-acceleration',  be = 1/6; ga = 1/2; af = 0;
  case 'hht-alpha',            be = (1 - alpha)^2/4; ga = 1/2 - alpha; af = -alpha;
  otherwise,                   be = 0; ga = 1/2; af = 0;   % central difference
end
e1 = [1; zeros(n - 1, 1)];
f = @(t, q) F*cos(omega*t) - knl*q(1)^3*e1;      % eq. (2)
lam = sort(eig(K, M)); out.n = n;
out.omega_max = sqrt(lam(end)); out.omega_max_h = out.omega_max*h;
if be == 0, out.h_stable = 2/out.omega_max; elseif be == 1/6, out.h_stable = 2*sqrt(3)/out.omega_max; end
N = ceil(t_end/h*(1 - 1e-12)); t = (0:N)*h;
s = ceil(N/(points - 1)); idx = unique([1:s:N + 1, N + 1]);   % the plotted steps
% the Newmark run, eqs. (3)-(5), at h and (for the order) again at h/2
for pass = 1:2
  hh = h/pass; NN = pass*N; tt = (0:NN)*hh;
  S = M + (1 - af)*(ga*hh*C + be*hh^2*K);        % (4) is linear in a1 with this matrix
  q = q0; v = v0; Fp = f(0, q); a = M \ (Fp - C*v - K*q); Q = zeros(n, N + 1); Q(:, 1) = q;
  E0 = v'*M*v/2 + q'*K*q/2; W = 0; D = 0; bal = 0; big = abs(E0); its = 0; R0 = 0; sc0 = 0;
  for k = 1:NN
    qt = q + hh*v + hh^2*(1/2 - be)*a; vt = v + hh*(1 - ga)*a;
    if af ~= 0, R0 = af*(C*v + K*q - Fp); sc0 = af*(norm(C*v, inf) + norm(K*q, inf) + norm(Fp, inf)); end
    if knl > 0 && be > 0                         % Newton on the residual of (4) (HHT-weighted)
      a1 = a;
      for it = 0:50
        q1 = qt + be*hh^2*a1; v1 = vt + ga*hh*a1; Fq = f(tt(k + 1), q1);
        r = M*a1 + (1 - af)*(C*v1 + K*q1 - Fq) + R0;
        if norm(r, inf) <= 1e-12*(norm(M*a1, inf) + sc0 + ...
            (1 - af)*(norm(C*v1, inf) + norm(K*q1, inf) + norm(Fq, inf))), break; end
        Kt = K + 3*knl*q1(1)^2*(e1*e1');
        a1 = a1 - (M + (1 - af)*(ga*hh*C + be*hh^2*Kt)) \ r; its = its + 1;
      end
    else                                         % linear in a1: one solve
      Fq = f(tt(k + 1), qt); a1 = S \ ((1 - af)*(Fq - C*vt - K*qt) - R0);
      q1 = qt + be*hh^2*a1; v1 = vt + ga*hh*a1;
    end
    % the trapezoidal rule in q, eq. (8)
    W = W + (q1 - q)'*(Fp + Fq)/2; D = D + (q1 - q)'*C*(v + v1)/2; Fp = Fq;
    E = v1'*M*v1/2 + q1'*K*q1/2; bal = max(bal, abs(E - E0 - W + D)); big = max([big, abs(E), abs(W), abs(D)]);
    q = q1; v = v1; a = a1;
    if mod(k, pass) == 0, Q(:, k/pass + 1) = q; end
  end
  if pass == 2                                  % eq. (6): the error falls as h^2
    e2 = max(max(abs(Q(:, idx) - Qx(:, idx))));
    out.observed_order = log2(err1/e2); out.work_done = W1; out.energy_dissipated = D1;
    break
  end
  W1 = W; D1 = D;
  out.energy_residual = bal/big; out.newton_iterations = its;
  wf = max(out.omega_max, omega);              % the fastest motion
  if knl == 0
    % eq. (9): the exact motion, state z = (q, q', cos wt, sin wt)
    G = [zeros(n), eye(n), zeros(n, 2); -M\K, -M\C, M\F, zeros(n, 1); ...
         zeros(1, 2*n), 0, -omega; zeros(1, 2*n), omega, 0];
    Z = zeros(2*n + 2, numel(idx)); Z(:, 1) = [q0; v0; 1; 0]; dk = diff(idx);
    Ps = expm(G*h*s); Pl = expm(G*h*dk(end));    % from one plotted step to the next
    for j = 2:numel(idx), if dk(j - 1) == s, Z(:, j) = Ps*Z(:, j - 1); else, Z(:, j) = Pl*Z(:, j - 1); end, end
    Qx = zeros(n, N + 1); Qx(:, idx) = Z(1:n, :);
    % eqs. (10)-(11): one step of the scheme as a linear map of (q, q', q'')
    S = M + (1 - af)*(ga*h*C + be*h^2*K);
    Ra = -S \ [K, C + (1 - af)*h*K, (1 - af)*(h*(1 - ga)*C + h^2*(1/2 - be)*K)];
    A = [eye(n), h*eye(n), h^2*(1/2 - be)*eye(n); zeros(n), eye(n), h*(1 - ga)*eye(n); zeros(n, 3*n)] ...
        + [be*h^2*Ra; ga*h*Ra; Ra];
    b = S \ F; B = [be*h^2*b; ga*h*b; b];
    Ah = [A, af*B + (1 - af)*B*cos(omega*h), -(1 - af)*B*sin(omega*h); ...
          zeros(2, 3*n), [cos(omega*h), -sin(omega*h); sin(omega*h), cos(omega*h)]];
    y = [q0; v0; M \ (F - C*v0 - K*q0); 1; 0]; dd = 0;
    As = Ah^s; Al = Ah^dk(end);                  % powers of Ah: from one plotted step to the next
    for j = 2:numel(idx)
      if dk(j - 1) == s, y = As*y; else, y = Al*y; end
      dd = max(dd, norm(y(1:n) - Q(:, idx(j)), inf));
    end
    out.discrete_difference = dd;
    % rounding of the powers at each plotted step, and eps per radian of omega t (force, modes)
    err_ref = eps*(8*numel(idx) + 2*(omega + out.omega_max)*N*h)*max(max(abs([Q(:, idx), Qx(:, idx)])));
  else
    % the reference: ode45 at a tight tolerance (the C code uses DOP853 at 1e-11)
    opts = odeset('RelTol', 1e-10, 'AbsTol', 1e-10*max(max(abs(Q(:, idx)))));
    ts = t(idx); if numel(ts) == 2, ts = [ts(1), mean(ts), ts(2)]; end
    [~, Y] = ode45(@(tt, y) [y(n+1:2*n); M \ (f(tt, y(1:n)) - C*y(n+1:2*n) - K*y(1:n))], ts, [q0; v0], opts);
    if numel(idx) == 2, Y = Y([1, 3], :); end
    Qx = zeros(n, N + 1); Qx(:, idx) = Y(:, 1:n)';
    out.newton_per_step = its/N;
    wt = sqrt(max(eig(K + 3*knl*max(max(abs(Qx(:, idx))))^2*(e1*e1'), M)));
    out.omega_max_tangent = wt; wf = max(wf, wt);
    err_ref = 1e-9*max(max(abs([Q(:, idx), Qx(:, idx)])));
  end
  d = Q(:, idx) - Qx(:, idx); err1 = max(abs(d(:))); out.max_error = err1;
  Aref = max(max(abs(Qx(:, idx)))); out.relative_error = err1/Aref;
  % the order only where the error is asymptotic: above the reference's, under 1 %
  if ~(err1 > 1e4*err_ref && err1 < 1e-2*Aref && wf*h <= 0.5), break; end
end
