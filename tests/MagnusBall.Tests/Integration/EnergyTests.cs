using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Tests.Integration
{
    /// <summary>The physics' own invariants: Magnus does no work, drag only removes energy.</summary>
    [TestFixture]
    public class EnergyTests
    {
        private static FlightState SpinningShot()
        {
            var velocity = new Vector3d(25, 4, 9);
            Vector3d spin = Spin.Topspin(velocity, Vector3d.UnitZ, 300) + Spin.Toward(velocity, Vector3d.UnitY, 120);
            return new FlightState(new Vector3d(0, 0, 1), velocity, spin);
        }

        [Test]
        public void MagnusForceDoesNoWork_EnergyConservedTo1e9Relative_Rk4At1ms()
        {
            // No drag, Stepanek lift and spin decay: the lift is perpendicular to the velocity at every instant.
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, null, StepanekLift.Instance, new ExponentialSpinDecay(3));
            FlightState state = SpinningShot();
            double e0 = model.MechanicalEnergy(state);
            FlightState end = Shots.Fly(model, RungeKutta4.Instance, state, 0.001, 2000);
            // The ball really curved: lift moved it sideways by metres, so the test is not vacuous.
            FlightState vacuumEnd = Shots.Fly(FlightModel.Vacuum(Ball.Tennis, Gravity.ZUp), RungeKutta4.Instance, state, 0.001, 2000);
            Assert.That(Vector3d.Distance(end.Position, vacuumEnd.Position), Is.GreaterThan(1.0));
            // 1e-9 relative: the bound; RK4's energy drift for a rotation-like force at 1 ms is ~(w h)^6.
            Assert.That(Math.Abs(model.MechanicalEnergy(end) - e0) / Math.Abs(e0), Is.LessThan(1e-9));
        }

        [Test]
        public void MagnusWithWind_DoesWork_SoTheInvariantAboveIsNotTrivial()
        {
            var model = new FlightModel(Ball.Tennis, new Air(1.21, new Vector3d(0, 0, 5)), Gravity.ZUp, null, StepanekLift.Instance);
            FlightState state = SpinningShot();
            FlightState end = Shots.Fly(model, RungeKutta4.Instance, state, 0.001, 2000);
            Assert.That(Math.Abs(model.MechanicalEnergy(end) - model.MechanicalEnergy(state)), Is.GreaterThan(1e-3));
        }

        [Test]
        public void ExplicitEuler_InAVacuum_GainsExactlyMgSquaredHSquaredOverTwoPerStep()
        {
            // Why the drag test below can hold for forward Euler only while drag dominates: with p' = p + v h and
            // v' = v + a h, dE = (F_drag . v) h + m |a|^2 h^2 / 2. In a vacuum the first term is 0 and Euler gains
            // m g^2 h^2 / 2 every step; the other three methods keep the energy (exact on the parabola) or lose it.
            FlightModel vacuum = FlightModel.Vacuum(Ball.Tennis, Gravity.ZUp);
            FlightState state = SpinningShot();
            const double step = 1.0 / 60;
            double e0 = vacuum.MechanicalEnergy(state);
            FlightState end = Shots.Fly(vacuum, ExplicitEuler.Instance, state, step, 120);
            double expected = 120 * 0.5 * Ball.Tennis.Mass * Gravity.Standard * Gravity.Standard * step * step;
            // 1e-12 J: rounding of 120 energy differences of ~10 J each.
            Assert.That(vacuum.MechanicalEnergy(end) - e0, Is.EqualTo(expected).Within(1e-12));
            Assert.That(vacuum.MechanicalEnergy(Shots.Fly(vacuum, SemiImplicitEuler.Instance, state, step, 120)), Is.LessThan(e0));
        }

        [TestCaseSource(typeof(Integrators), nameof(Integrators.All))]
        public void WithDrag_EnergyNeverIncreases_AtAnyStep(IIntegrator integrator)
        {
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(3));
            FlightState state = SpinningShot();
            const double step = 1.0 / 120;
            StateDerivative derivative = model.Derivative(state);
            double energy = model.MechanicalEnergy(state);
            for (int i = 0; i < 480; i++)
            {
                FlightState next = integrator.Step(model, state, derivative, step);
                double nextEnergy = model.MechanicalEnergy(next);

                // Rounding of E = m(v^2/2 - g.p), a sum of terms no larger than |E| + m|g||p|.
                double rounding = 1e-13 * (Math.Abs(energy) + model.Ball.Mass * Gravity.Standard * next.Position.Length);

                Assert.That(nextEnergy - energy, Is.LessThanOrEqualTo(rounding), $"{integrator.Name} step {i} at t={state.Time:F4}");

                state = next;
                derivative = model.Derivative(state);
                energy = nextEnergy;
            }

            Assert.That(energy, Is.LessThan(model.MechanicalEnergy(SpinningShot()) * 0.9), "drag removed energy");
        }
    }
}
