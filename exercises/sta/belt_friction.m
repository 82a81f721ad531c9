% Capstan equation: the belt on the verge of slipping toward the tight side.
mue = mu / sin(beta);               % a V-groove of half-angle beta presses 1/sin(beta) harder
out.ratio = exp(mue * theta);
out.T2 = T1 * out.ratio;            % largest tension T1 can hold
out.T2_min = T1 / out.ratio;        % below this the belt slips the other way
out.torque = (out.T2 - T1) * r;
out.mu_eff = mue;
% the same belt over n sharp pegs converges to T2 like 1/n^2
for n = [8 64 512]
  s = mue * sin(theta / (2 * n));
  Tn = T1 * ((1 + s) / (1 - s))^n;
  fprintf('%4d pegs: T2 = %.10g N (error %.3g N)\n', n, Tn, Tn - out.T2);
end
