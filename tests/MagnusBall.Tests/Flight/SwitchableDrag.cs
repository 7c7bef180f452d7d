using System;
using MagnusBall.Aerodynamics;

namespace MagnusBall.Tests.Flight
{
    /// <summary>A user's drag law (C_D = 0.5 + 0.05 S) that throws while <see cref="Throw"/> is set: the failing user code of the throw tests.</summary>
    internal sealed class SwitchableDrag : IDragModel
    {
        public bool Throw;

        public double DragCoefficient(in AeroConditions conditions) =>
            Throw ? throw new InvalidOperationException("the user's drag law failed") : 0.5 + 0.05 * conditions.SpinParameter;
    }
}
