#nullable enable
using System;
using MagnusBall.Flight;
using UnityEngine.Events;

namespace MagnusBall.Components
{
    /// <summary>
    /// A UnityEvent that passes the <see cref="FlightEvent"/> (its kind, exact time, state, and for a bounce the state
    /// after): the type of <see cref="MagnusBallFlight"/>'s inspector events, so that methods taking a FlightEvent can be
    /// wired in the inspector, and code can call <c>AddListener</c>.
    /// </summary>
    [Serializable]
    public class FlightEventUnityEvent : UnityEvent<FlightEvent>
    {
    }
}
