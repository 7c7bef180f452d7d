// UnityEngine.Events and UnityEngine.Serialization, as far as MagnusBall.Unity uses them (Unity 6000.0's signatures:
// artifacts/generated/UnityEvent/UnityEvent_0.cs and _1.cs, Runtime/Export/Serialization/FormerlySerializedAsAttribute.cs).
// Unity's UnityEvent and UnityEvent<T0> derive from UnityEventBase (persistent calls set in the inspector); the stub omits
// the base and keeps only the listeners added in code, which Invoke calls in the order they were added.
using System;
using System.Collections.Generic;

namespace UnityEngine.Events
{
    public delegate void UnityAction();

    public delegate void UnityAction<T0>(T0 arg0);

    [Serializable]
    public class UnityEvent
    {
        private readonly List<UnityAction> _calls = new List<UnityAction>();

        public UnityEvent()
        {
        }

        public void AddListener(UnityAction call) => _calls.Add(call);

        public void RemoveListener(UnityAction call) => _calls.Remove(call);

        // Unity invokes a snapshot of the list: a listener added or removed during Invoke changes the next Invoke only.
        public void Invoke()
        {
            foreach (UnityAction call in _calls.ToArray())
            {
                call();
            }
        }
    }

    [Serializable]
    public class UnityEvent<T0>
    {
        private readonly List<UnityAction<T0>> _calls = new List<UnityAction<T0>>();

        public UnityEvent()
        {
        }

        public void AddListener(UnityAction<T0> call) => _calls.Add(call);

        public void RemoveListener(UnityAction<T0> call) => _calls.Remove(call);

        // As UnityEvent.Invoke: a snapshot of the listeners.
        public void Invoke(T0 arg0)
        {
            foreach (UnityAction<T0> call in _calls.ToArray())
            {
                call(arg0);
            }
        }
    }
}

namespace UnityEngine.Serialization
{
    [AttributeUsage(AttributeTargets.Field, AllowMultiple = true, Inherited = false)]
    public class FormerlySerializedAsAttribute : Attribute
    {
        private readonly string m_oldName;

        public FormerlySerializedAsAttribute(string oldName) => m_oldName = oldName;

        public string oldName => m_oldName;
    }
}
