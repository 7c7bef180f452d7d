using System;
using System.Collections.Generic;
using MagnusBall.Aerodynamics;
using NUnit.Framework;

namespace MagnusBall.Tests.Aerodynamics
{
    /// <summary>
    /// Every bound the law catalogue states (Aerodynamics/LawCatalogue.cs: at least |C| for a drag or lift law, at least
    /// |dw/dt| / |w| for a spin decay) holds for that law over the inputs a flight can give it. The stability shortcut
    /// (FlightModel.StiffnessSurelyBelow) trusts these bounds to skip computing the stiffness rate, so a bound that a
    /// law exceeds would let an unstable step through. The laws are the catalogue's own examples, so a new law with a
    /// bound is checked without a line here.
    /// </summary>
    public class CatalogueBoundTests
    {
        // Speeds 0 to 300 m/s (past any ball's launch), spins 0 to 20,000 rad/s (past any measured spin), the presets'
        // radii, sea-level to thin and dense air, and the transverse share of the spin from none to all of it.
        private static IEnumerable<AeroConditions> Inputs()
        {
            double[] speeds = { 0, 1e-9, 0.5, 3, 10, 25, 45, 70, 120, 300 };
            double[] spins = { 0, 1, 30, 150, 400, 1000, 3000, 20000 };
            double[] radii = { 0.02, 0.0213, 0.033, 0.0366, 0.11, 0.12 };
            double[] densities = { 0.6, 1.225, 1.5 };
            double[] transverseShares = { 0, 0.3, 1 };
            foreach (double speed in speeds)
            foreach (double spin in spins)
            foreach (double radius in radii)
            foreach (double density in densities)
            foreach (double share in transverseShares)
            {
                yield return new AeroConditions(speed, spin, spin * share, radius, density, Air.SeaLevel.DynamicViscosity);
            }
        }

        [Test]
        public void EveryStatedDragAndLiftBound_HoldsForItsLaw()
        {
            int bounded = 0;
            foreach (IDragModel drag in LawCatalogue.DragExamples())
            {
                if (LawCatalogue.TraitsOf(drag).Bound is double bound)
                {
                    bounded++;
                    foreach (AeroConditions c in Inputs())
                    {
                        Assert.That(Math.Abs(drag.DragCoefficient(c)), Is.LessThanOrEqualTo(bound), $"{drag} at {c.Speed} m/s, S = {c.SpinParameter}");
                    }
                }
            }

            foreach (ILiftModel lift in LawCatalogue.LiftExamples())
            {
                if (LawCatalogue.TraitsOf(lift).Bound is double bound)
                {
                    bounded++;
                    foreach (AeroConditions c in Inputs())
                    {
                        Assert.That(Math.Abs(lift.LiftCoefficient(c)), Is.LessThanOrEqualTo(bound), $"{lift} at {c.Speed} m/s, S_perp = {c.TransverseSpinParameter}");
                    }
                }
            }

            // Constant drag and lift, Stepanek's drag and lift: the catalogue's bounded laws today.
            Assert.That(bounded, Is.GreaterThanOrEqualTo(4));
        }

        [Test]
        public void EveryStatedSpinDecayBound_HoldsForItsLaw()
        {
            int bounded = 0;
            var spin = new Vector3d(0, 300, 40);
            foreach (ISpinDecayModel decay in LawCatalogue.SpinDecayExamples())
            {
                if (LawCatalogue.TraitsOf(decay).Bound is double bound)
                {
                    bounded++;
                    foreach (AeroConditions c in Inputs())
                    {
                        double rate = decay.SpinAcceleration(spin, c).Length / spin.Length;
                        // 1e-15: the rate is |c w| / |w|, two vector lengths and a division, each rounded (about 2.2e-16 apiece).
                        Assert.That(rate, Is.LessThanOrEqualTo(bound * (1 + 1e-15)), $"{decay} at {c.Speed} m/s");
                    }
                }
            }

            Assert.That(bounded, Is.GreaterThanOrEqualTo(1));
        }
    }
}
