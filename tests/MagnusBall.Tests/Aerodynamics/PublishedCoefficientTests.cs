using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Tests.Aerodynamics
{
    /// <summary>The published coefficient models: their printed values, their limits and their continuity.</summary>
    [TestFixture]
    public class PublishedCoefficientTests
    {
        private static AeroConditions At(double speed, double spin, double radius) =>
            new AeroConditions(speed, spin, spin, radius, 1.225, Air.SeaLevelDynamicViscosity);

        /// <summary>
        /// Largest jump between neighbouring samples 1e-6 apart in the argument over [from, to]: for a
        /// continuous law with slope at most L it is at most L * 1e-6.
        /// </summary>
        private static double LargestJump(Func<double, double> f, double from, double to)
        {
            const double h = 1e-6;
            double largest = 0;
            int n = 200_000;
            for (int i = 0; i < n; i++)
            {
                double x = from + (to - from) * i / n;
                largest = Math.Max(largest, Math.Abs(f(x + h) - f(x)));
            }

            return largest;
        }

        [Test]
        public void GoffCarreDrag_PrintedValuesAndTheCrisis()
        {
            // The logistic's limits and midpoint: 0.501 far below, 0.155 far above, 0.155 + 0.173 at 12.19 m/s.
            Assert.That(GoffCarreSoccerDrag.NonSpinning(0), Is.EqualTo(0.155 + 0.346 / (1 + Math.Exp(-12.19 / 1.309))).Within(1e-15));
            Assert.That(GoffCarreSoccerDrag.NonSpinning(12.19), Is.EqualTo(0.155 + 0.173).Within(1e-15));
            Assert.That(GoffCarreSoccerDrag.NonSpinning(40), Is.EqualTo(0.155).Within(1e-9));
            Assert.That(GoffCarreSoccerDrag.Spinning(0.3), Is.EqualTo(0.4127 * Math.Pow(0.3, 0.3056)).Within(1e-15));
            Assert.That(GoffCarreSoccerDrag.Spinning(0), Is.EqualTo(0));
            // The combination is the larger of the two: slow, the crisis curve; fast and spinning, the spin law.
            Assert.That(GoffCarreSoccerDrag.Evaluate(5, 0.3), Is.EqualTo(GoffCarreSoccerDrag.NonSpinning(5)));
            Assert.That(GoffCarreSoccerDrag.Evaluate(25, 0.3), Is.EqualTo(GoffCarreSoccerDrag.Spinning(0.3)));
            Assert.That(GoffCarreSoccerDrag.Instance.DragCoefficient(At(25, 0.3 * 25 / 0.11, 0.11)), Is.EqualTo(GoffCarreSoccerDrag.Spinning(0.3)).Within(1e-12));
        }

        [Test]
        public void GoffCarreDrag_IsContinuousThroughTheDragCrisis_AndWhereTheTwoLawsMeet()
        {
            // Steepest slope of the logistic is 0.346/(4*1.309) = 0.066 per m/s: a 1e-6 step moves it at most 6.6e-8.
            double crisis = LargestJump(v => GoffCarreSoccerDrag.Evaluate(v, 0), 0, 40);
            Assert.That(crisis, Is.LessThan(1e-7));
            // Along S at 25 m/s the max switches from 0.155 to the spin law near S = 0.03; the spin law's slope
            // there is 0.4127*0.3056*S^-0.69 ~ 1.4: a jump-free switch moves at most ~1.4e-6 per 1e-6 step.
            double switchOver = LargestJump(s => GoffCarreSoccerDrag.Evaluate(25, s), 0.005, 1);
            Assert.That(switchOver, Is.LessThan(2e-6));
        }

        [Test]
        public void SoccerLiftTable_HitsItsPointsInterpolatesAndHoldsTheEnd()
        {
            PiecewiseLinearLift lift = PiecewiseLinearLift.SoccerGoffCarre;
            Assert.That(lift.Evaluate(0.11), Is.EqualTo(0.22));
            Assert.That(lift.Evaluate(0.27), Is.EqualTo(0.29));
            Assert.That(lift.Evaluate(0.71), Is.EqualTo(0.31));
            Assert.That(lift.Evaluate(0.135), Is.EqualTo(0.23).Within(1e-15));
            Assert.That(lift.Evaluate(2.0), Is.EqualTo(0.31), "held beyond the last point");
            Assert.That(lift.Evaluate(0), Is.EqualTo(0));
            Assert.That(lift.LiftCoefficient(At(20, 0.2 * 20 / 0.11, 0.11)), Is.EqualTo(0.29).Within(1e-12));
            // Steepest segment: (0.22 - 0.05)/0.06 = 2.83 per unit S; a 1e-6 step moves it at most 2.9e-6.
            Assert.That(LargestJump(lift.Evaluate, 0, 1), Is.LessThan(3e-6));
        }

        [Test]
        public void GolfModels_PrintedValuesAndContinuity()
        {
            PiecewiseLinearLift lift = PiecewiseLinearLift.GolfSmitsSmith;
            Assert.That(lift.Evaluate(0.04), Is.EqualTo(0.10));
            Assert.That(lift.Evaluate(0.30), Is.EqualTo(0.28).Within(1e-15));
            Assert.That(lift.Evaluate(0.8), Is.EqualTo(0.33));
            // Steepest segment: 0.10/0.04 = 2.5 per unit S.
            Assert.That(LargestJump(lift.Evaluate, 0, 1), Is.LessThan(2.6e-6));
            Assert.That(LinearSpinDrag.GolfSmitsSmith.DragCoefficient(At(70, 0.1 * 70 / 0.021335, 0.021335)), Is.EqualTo(0.24 + 0.18 * 0.1).Within(1e-12));
        }

        [Test]
        public void NathanBaseball_PrintedValuesLimitsAndContinuity()
        {
            Assert.That(NathanBaseballDrag.Evaluate(0), Is.EqualTo(0.3008));
            Assert.That(NathanBaseballDrag.Evaluate(2000), Is.EqualTo(0.3008 + 0.0584).Within(1e-15));
            Assert.That(NathanBaseballDrag.Instance.DragCoefficient(At(40, Spin.FromRpm(2000), 0.0366)), Is.EqualTo(0.3592).Within(1e-12));
            Assert.That(NathanBaseballLift.Evaluate(0), Is.EqualTo(0));
            Assert.That(NathanBaseballLift.Evaluate(0.2), Is.EqualTo(1.120 * 0.2 / (0.583 + 2.333 * 0.2)).Within(1e-15));
            Assert.That(NathanBaseballLift.Evaluate(1e12), Is.EqualTo(1.120 / 2.333).Within(1e-9));
            // Slope is largest at S = 0: 1.120/0.583 = 1.92.
            Assert.That(LargestJump(NathanBaseballLift.Evaluate, 0, 1), Is.LessThan(2e-6));
        }

        [Test]
        public void TennisSpinDecay_Loses2PercentOver6Point4Metres_AtAnySpeed()
        {
            foreach (double speed in new[] { 15.0, 30.0 })
            {
                var model = new FlightModel(Ball.Tennis, new Air(1.21), new Vector3d(0, 0, 0), spinDecay: SpeedProportionalSpinDecay.TennisCrossLindsey);
                var state = new FlightState(Vector3d.Zero, new Vector3d(speed, 0, 0), new Vector3d(0, 200, 0));
                int steps = 1000;
                FlightState end = Shots.Fly(model, RungeKutta4.Instance, state, 6.4 / speed / steps, steps);
                // 1e-9: RK4 on an exponential over 1000 steps; the law is exact exp(-k * distance).
                Assert.That(end.AngularVelocity.Y / 200, Is.EqualTo(0.98).Within(1e-9), $"at {speed} m/s");
            }
        }

        [Test]
        public void BaseballSpinDecay_HasATimeConstantOf5SecondsAt100Mph()
        {
            var conditions = At(44.704, 200, 0.0366);
            Vector3d rate = SpeedProportionalSpinDecay.BaseballNathan.SpinAcceleration(new Vector3d(0, 200, 0), conditions);
            Assert.That(-200 / rate.Y, Is.EqualTo(5).Within(1e-12));
        }

        [Test]
        public void BadTablesAndLaws_AreRefusedNamingTheParameter()
        {
            Assert.That(() => new PiecewiseLinearLift(new double[0], new double[0]), Throws.InstanceOf<ArgumentException>().With.Message.Contains("spinParameters"));
            Assert.That(() => new PiecewiseLinearLift(new[] { 0.0, 0.1 }, new[] { 0.0 }), Throws.InstanceOf<ArgumentException>().With.Message.Contains("spinParameters"));
            Assert.That(() => new PiecewiseLinearLift(new[] { 0.0, 0.0 }, new[] { 0.0, 0.1 }), Throws.InstanceOf<ArgumentException>().With.Message.Contains("increasing"));
            Assert.That(() => new PiecewiseLinearLift(new[] { 0.0, 0.1 }, new[] { 0.0, double.NaN }), Throws.InstanceOf<ArgumentException>().With.Message.Contains("liftCoefficients"));
            Assert.That(() => new LinearSpinDrag(-0.1, 0.1), Throws.InstanceOf<ArgumentException>().With.Message.Contains("intercept"));
            Assert.That(() => new LinearSpinDrag(0.2, double.NaN), Throws.InstanceOf<ArgumentException>().With.Message.Contains("slope"));
            Assert.That(() => new SpeedProportionalSpinDecay(-1), Throws.InstanceOf<ArgumentException>().With.Message.Contains("ratePerMetre"));
            Assert.That(() => SpeedProportionalSpinDecay.FromLossOverDistance(1, 6.4), Throws.InstanceOf<ArgumentException>().With.Message.Contains("fraction"));
            Assert.That(() => SpeedProportionalSpinDecay.FromLossOverDistance(0.02, 0), Throws.InstanceOf<ArgumentException>().With.Message.Contains("distanceMetres"));
        }
    }
}
