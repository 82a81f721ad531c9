% vib-chain-modes: n masses on n+1 (fixed-fixed) or n (fixed-free) springs
e = ones(n, 1); K = k*(2*diag(e) - diag(e(1:n-1), 1) - diag(e(1:n-1), -1));
if strcmp(ends, 'fixed-free'), K(n, n) = k; end
M = m*eye(n);
lam = sort(eig(K, M)); w = sqrt(max(lam(1:modes), 0));   % the computer's frequencies
j = (1:modes)';
if strcmp(ends, 'fixed-free')
  th = (2*j - 1)*pi/(2*(2*n + 1));                       % eq. (3)
else
  th = j*pi/(2*(n + 1));                                  % eq. (2)
end
wx = 2*sqrt(k/m)*sin(th);
out.max_rel_error = max(abs(w./wx - 1));
out.rounding_bound_mode1 = 8*eps*4*k/m/wx(1)^2;           % eq. (5): ~ n^2 eps
out.omega1 = wx(1);
