% num-polyfit: the least-squares polynomial by MATLAB's polyfit (eqs. 1-3).
c = polyfit(x, y, degree);                   % coefficients, highest power first
for k = 0:degree
    out.(sprintf('c%d', k)) = c(k + 1);
end
r = y - polyval(c, x);                       % residuals, eq. (2)
out.rms_residual = sqrt(sum(r.^2) / numel(x));
t = (x(:) - mean(x)) / max(abs(x - mean(x)));  % centred and scaled x
out.cond = cond(t .^ (degree:-1:0));         % the least-squares matrix in t
