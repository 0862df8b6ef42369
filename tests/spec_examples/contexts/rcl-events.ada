with RCL.Events;
with RCL.Publishers;
--  DECLARATIONS
Pub : Publishers.Publisher;
