using MagnusBall.Integration;

namespace MagnusBall.Cli
{
    /// <summary>
    /// The stability check of a plain explicit method's fixed step, for simulate and aim alike: a step whose h sigma (the
    /// step times the library's stiffness rate, which bounds the drag eigenvalue 2 k C_D s and adds the Magnus and
    /// spin-decay rates; StableIntegrator's remarks) is beyond the method's stability bound on the real axis, h |lambda|
    /// &lt;= 2 for the Euler methods and Heun and 2.785 for RK4 and 3.3 for Dormand-Prince, capped at the 2.5 the
    /// library's StableIntegrator accepts, is refused before it is taken. stable-rk4 splits such a step itself.
    /// </summary>
    internal static class StabilityCheck
    {
        /// <summary>The check for <paramref name="integrator"/> (the library's rule): null for stable-rk4.</summary>
        public static StableIntegrator? For(IIntegrator integrator) => StableIntegrator.AtStabilityBound(integrator);

        /// <summary>Throws an <see cref="InputError"/> at <paramref name="path"/> when <paramref name="step"/> from <paramref name="state"/> is beyond the bound.</summary>
        public static void Require(StableIntegrator? bound, IIntegrator integrator, FlightModel model, in FlightState state, double step, string path)
        {
            if (bound is null || !(step > 0) || bound.SubstepCount(model, state, step) <= 1)
            {
                return;
            }

            double largest = LargestStableStep(bound, model, state, step);
            throw new InputError(path,
                $"a step of {JsonFields.Format(step)} s is beyond {integrator.Name}'s stability bound for this flight's drag " +
                $"at t = {JsonFields.Format(state.Time)} s ({JsonFields.Format(state.Velocity.Length)} m/s); " +
                (largest > 0
                    ? $"the largest stable step there is {JsonFields.Format(largest)} s: use a step of at most that, or stable-rk4, which splits a step into stable substeps"
                    : "no positive step is stable there (the drag rate overflows a double): check the speed and the ball"));
        }

        /// <summary>
        /// The largest step below <paramref name="step"/> that <paramref name="bound"/> takes whole: halvings down to the
        /// first stable step (at most 1,100, past the smallest double), then 60 bisections between it and its double.
        /// 0 where no positive step is stable (a speed whose drag rate overflows).
        /// </summary>
        public static double LargestStableStep(StableIntegrator bound, FlightModel model, in FlightState state, double step)
        {
            double unstable = step, stable = 0.5 * step;
            for (int k = 0; k < 1100 && stable > 0 && bound.SubstepCount(model, state, stable) > 1; k++)
            {
                unstable = stable;
                stable *= 0.5;
            }

            if (!(stable > 0) || bound.SubstepCount(model, state, stable) > 1)
            {
                return 0;
            }

            for (int i = 0; i < 60; i++)
            {
                double mid = 0.5 * (stable + unstable);
                if (!(mid > stable && mid < unstable))
                {
                    break;
                }

                if (bound.SubstepCount(model, state, mid) > 1)
                {
                    unstable = mid;
                }
                else
                {
                    stable = mid;
                }
            }

            return stable;
        }
    }
}
