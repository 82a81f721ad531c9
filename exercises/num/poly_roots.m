% num-poly-roots: every root of p by MATLAB's roots (the eigenvalues of
% the companion matrix, eq. 3), each with its first-order error (eq. 5).
z = roots(p);
q = p(find(p ~= 0, 1):end);                  % leading zeros lower the degree
out.degree = numel(q) - 1;
d = numel(q) - 1;
dq = q(1:end-1) .* (d:-1:1);                 % p'
% a change of eps/2 in every coefficient moves a simple root by about this
% (a cluster of m roots moves by about eps^(1/m): more than this says)
err = eps/2 * polyval(abs(q), abs(z)) ./ abs(polyval(dq, z));
out.real_roots = sum(abs(imag(z)) <= err);   % a root whose error disc meets the real axis is real
if isempty(err)
    out.max_err = 0;
else
    out.max_err = max(err);
end
